// World queries: bounding boxes, points and rays, each in ascending slot order. The broad
// phase's trees give the bodies near the query; each is then tested exactly.
#include "core/error.h"
#include "core/world.h"
#include "core/solver/world_state.h"

#include <algorithm>
#include <string>

namespace impulse2d {

namespace {
void require_finite_query(vec2 value, const char* caller, const char* name) {
  if (!is_finite(value)) throw Error(std::string(caller) + ": " + name + " is not finite");
}
}  // namespace

void World::query_aabb(const Aabb& box, const QueryCallback& callback) const {
  require_finite_query(box.lower, "World::query_aabb", "box.lower");
  require_finite_query(box.upper, "World::query_aabb", "box.upper");
  std::vector<std::uint32_t> nearby;
  state_->broad_phase.query(box, nearby);
  for (const std::uint32_t i : nearby) {
    if (!state_->alive[i]) continue;  // the callback may have removed it
    const Aabb bounds = body_aabb(state_->bodies[i]);
    if (bounds.overlaps(box) && !callback(state_->bodies[i].id)) return;
  }
}

void World::query_point(vec2 point, const QueryCallback& callback) const {
  require_finite_query(point, "World::query_point", "point");
  std::vector<std::uint32_t> nearby;
  state_->broad_phase.query(Aabb{point, point}, nearby);
  for (const std::uint32_t i : nearby) {
    if (!state_->alive[i]) continue;  // the callback may have removed it
    if (body_contains_point(state_->bodies[i], point) &&
        !callback(state_->bodies[i].id)) {
      return;
    }
  }
}

std::vector<RayHit> World::raycast_all(vec2 origin, vec2 translation, std::uint32_t layers) const {
  require_finite_query(origin, "World::raycast", "origin");
  require_finite_query(translation, "World::raycast", "translation");
  std::vector<RayHit> hits;
  std::vector<std::uint32_t> nearby;
  state_->broad_phase.raycast(origin, translation, nearby);
  for (const std::uint32_t i : nearby) {
    const Body& body = state_->bodies[i];
    if (!state_->alive[i] || (body.collision_layers & layers) == 0) continue;
    ShapeRayHit shape_hit;
    if (raycast_body(body, origin, translation, layers, true, &shape_hit)) {
      hits.push_back(
          RayHit{body.id, origin + translation * shape_hit.fraction, shape_hit.normal, shape_hit.fraction});
    }
  }
  // Stable sort keeps slot order among equal fractions.
  std::stable_sort(hits.begin(), hits.end(),
                   [](const RayHit& a, const RayHit& b) { return a.fraction < b.fraction; });
  return hits;
}

std::optional<RayHit> World::raycast_closest(vec2 origin, vec2 translation, std::uint32_t layers) const {
  require_finite_query(origin, "World::raycast", "origin");
  require_finite_query(translation, "World::raycast", "translation");
  std::optional<RayHit> closest;
  std::vector<std::uint32_t> nearby;
  state_->broad_phase.raycast(origin, translation, nearby);
  for (const std::uint32_t i : nearby) {
    const Body& body = state_->bodies[i];
    if (!state_->alive[i] || (body.collision_layers & layers) == 0) continue;
    ShapeRayHit shape_hit;
    if (raycast_body(body, origin, translation, layers, true, &shape_hit) &&
        (!closest || shape_hit.fraction < closest->fraction)) {
      closest = RayHit{body.id, origin + translation * shape_hit.fraction, shape_hit.normal,
                       shape_hit.fraction};
    }
  }
  return closest;
}

}  // namespace impulse2d

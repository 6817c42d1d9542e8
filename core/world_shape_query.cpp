// Shape queries (query.h): overlap of a placed shape, shape casts and filtered ray casts, found
// through the broad phase's trees without allocating, answered in slot order (ties by slot),
// so a world restored from a snapshot (whose trees are built afresh) answers alike.
#include "core/collide.h"
#include "core/error.h"
#include "core/query.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <cmath>
#include <string>

namespace impulse2d {

namespace {

// A shape as GJK sees it: world vertices (a circle's centre alone) and a radius.
struct Hull {
  vec2 vertices[max_polygon_vertices];
  int count = 0;
  float radius = 0.0f;
};

Hull hull_of(const Shape& shape, const Transform& transform) {
  Hull hull;
  switch (shape.type()) {
    case ShapeType::Circle:
      hull.vertices[0] = transform.position;
      hull.count = 1;
      hull.radius = shape.circle().radius;
      return hull;
    case ShapeType::Box: {
      const Polygon polygon = box_as_polygon(shape.box());
      for (int i = 0; i < polygon.count; ++i) hull.vertices[i] = transform.apply(polygon.vertices[i]);
      hull.count = polygon.count;
      return hull;
    }
    case ShapeType::Polygon:
      for (int i = 0; i < shape.polygon().count; ++i) {
        hull.vertices[i] = transform.apply(shape.polygon().vertices[i]);
      }
      hull.count = shape.polygon().count;
      hull.radius = shape.polygon().rounding;
      return hull;
    case ShapeType::Capsule:
      hull.vertices[0] = transform.apply(shape.capsule().center1);
      hull.vertices[1] = transform.apply(shape.capsule().center2);
      hull.count = 2;
      hull.radius = shape.capsule().radius;
      return hull;
    case ShapeType::Segment:
      hull.vertices[0] = transform.apply(shape.segment().point1);
      hull.vertices[1] = transform.apply(shape.segment().point2);
      hull.count = 2;
      return hull;
  }
  return hull;
}

int support(const Hull& hull, vec2 direction) {
  int best = 0;
  float best_dot = glm::dot(hull.vertices[0], direction);
  for (int i = 1; i < hull.count; ++i) {
    const float d = glm::dot(hull.vertices[i], direction);
    if (d > best_dot) {
      best_dot = d;
      best = i;
    }
  }
  return best;
}

struct SimplexVertex {
  vec2 w;      // vertex of B minus vertex of A
  int a = 0;   // index in A
  int b = 0;   // index in B
  float weight = 1.0f;
};

// Closest point to the origin of the segment (s[0], s[1]); reduces `count` to the vertices
// that make it and fills their weights.
vec2 solve_segment(SimplexVertex* s, int& count) {
  const vec2 e = s[1].w - s[0].w;
  const float t = -glm::dot(s[0].w, e) / glm::dot(e, e);
  if (!(t > 0.0f)) {
    count = 1;
    s[0].weight = 1.0f;
    return s[0].w;
  }
  if (t >= 1.0f) {
    s[0] = s[1];
    count = 1;
    s[0].weight = 1.0f;
    return s[0].w;
  }
  s[0].weight = 1.0f - t;
  s[1].weight = t;
  return s[0].w + e * t;
}

// Core (radius-free) distance of two hulls by GJK: returns false when the cores overlap.
bool core_distance(const Hull& a, const Hull& b, vec2& point_a, vec2& point_b) {
  SimplexVertex simplex[3];
  int count = 1;
  simplex[0].a = 0;
  simplex[0].b = 0;
  simplex[0].w = b.vertices[0] - a.vertices[0];
  vec2 closest = simplex[0].w;
  for (int iteration = 0; iteration < 32; ++iteration) {
    if (count == 2) {
      closest = solve_segment(simplex, count);
    } else if (count == 3) {
      // Inside the triangle: the cores overlap. Else the nearest of its edges.
      const float area = cross(simplex[1].w - simplex[0].w, simplex[2].w - simplex[0].w);
      const float c0 = cross(simplex[1].w, simplex[2].w);
      const float c1 = cross(simplex[2].w, simplex[0].w);
      const float c2 = cross(simplex[0].w, simplex[1].w);
      if ((area > 0.0f && c0 >= 0.0f && c1 >= 0.0f && c2 >= 0.0f) ||
          (area < 0.0f && c0 <= 0.0f && c1 <= 0.0f && c2 <= 0.0f)) {
        return false;
      }
      SimplexVertex best[3];
      int best_count = 0;
      float best_length = 0.0f;
      vec2 best_closest{0.0f};
      const int edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
      for (const auto& edge : edges) {
        SimplexVertex trial[3] = {simplex[edge[0]], simplex[edge[1]], {}};
        int trial_count = 2;
        const vec2 point = solve_segment(trial, trial_count);
        const float length = glm::dot(point, point);
        if (best_count == 0 || length < best_length) {
          best_length = length;
          best_closest = point;
          best_count = trial_count;
          best[0] = trial[0];
          best[1] = trial[1];
        }
      }
      simplex[0] = best[0];
      simplex[1] = best[1];
      count = best_count;
      closest = best_closest;
    } else {
      simplex[0].weight = 1.0f;
    }
    const float length_squared_now = glm::dot(closest, closest);
    if (length_squared_now < 1.0e-12f) return false;
    // New support point in the direction of the origin.
    const vec2 direction = -closest;
    SimplexVertex vertex;
    vertex.a = support(a, -direction);
    vertex.b = support(b, direction);
    vertex.w = b.vertices[vertex.b] - a.vertices[vertex.a];
    bool repeated = false;
    for (int i = 0; i < count; ++i) repeated = repeated || (simplex[i].a == vertex.a && simplex[i].b == vertex.b);
    // No progress towards the origin: `closest` is the answer.
    if (repeated || length_squared_now - glm::dot(closest, vertex.w) <= 1.0e-6f * length_squared_now) break;
    simplex[count++] = vertex;
  }
  point_a = vec2(0.0f);
  point_b = vec2(0.0f);
  for (int i = 0; i < count; ++i) {
    point_a += a.vertices[simplex[i].a] * simplex[i].weight;
    point_b += b.vertices[simplex[i].b] * simplex[i].weight;
  }
  return true;
}

ShapeDistance hull_distance(const Hull& a, const Hull& b) {
  ShapeDistance result;
  vec2 core_a, core_b;
  if (!core_distance(a, b, core_a, core_b)) return result;
  const vec2 between = core_b - core_a;
  const float core = std::sqrt(glm::dot(between, between));
  if (!(core > 0.0f)) return result;
  const vec2 normal = between / core;
  const float distance = core - a.radius - b.radius;
  if (!(distance > 0.0f)) return result;
  result.distance = distance;
  result.normal = normal;
  result.point_a = core_a + normal * a.radius;
  result.point_b = core_b - normal * b.radius;
  return result;
}

void require_finite_query(vec2 value, const char* caller, const char* name) {
  if (!is_finite(value)) throw Error(std::string(caller) + ": " + name + " is not finite");
}

void require_query_shape(const Shape& shape, const Transform& transform, const char* caller) {
  require_finite_query(transform.position, caller, "transform.position");
  if (!(std::isfinite(transform.rotation.cosine) && std::isfinite(transform.rotation.sine))) {
    throw Error(std::string(caller) + ": transform.rotation is not finite");
  }
  bool valid = true;
  switch (shape.type()) {
    case ShapeType::Circle: valid = shape.circle().radius > 0.0f && std::isfinite(shape.circle().radius); break;
    case ShapeType::Box: valid = shape.box().half_extents.x > 0.0f && shape.box().half_extents.y > 0.0f &&
                                 is_finite(shape.box().half_extents); break;
    case ShapeType::Polygon: valid = shape.polygon().count >= 3 && shape.polygon().count <= max_polygon_vertices &&
                                     shape.polygon().rounding >= 0.0f && std::isfinite(shape.polygon().rounding); break;
    case ShapeType::Capsule: valid = shape.capsule().radius > 0.0f && std::isfinite(shape.capsule().radius) &&
                                     is_finite(shape.capsule().center1) && is_finite(shape.capsule().center2) &&
                                     shape.capsule().center1 != shape.capsule().center2; break;
    case ShapeType::Segment: valid = is_finite(shape.segment().point1) && is_finite(shape.segment().point2) &&
                                     shape.segment().point1 != shape.segment().point2; break;
  }
  if (!valid) {
    throw Error(std::string(caller) +
                ": invalid shape (make it with make_circle, make_box, make_polygon, make_capsule or make_segment)");
  }
}

// A box turns with the query's rotation: the narrow phase's boxes never turn, so a turned box
// is asked as the polygon of its outline.
Shape as_placed(const Shape& shape, const Transform& transform) {
  if (shape.type() == ShapeType::Box &&
      (transform.rotation.sine != 0.0f || transform.rotation.cosine != 1.0f)) {
    return Shape(box_as_polygon(shape.box()));
  }
  return shape;
}

bool passes(const WorldState& world, std::uint32_t slot, const QueryFilter& filter) {
  if (!world.alive[slot]) return false;
  const Body& body = world.bodies[slot];
  if ((body.collision_layers & filter.layers) == 0) return false;
  if (body.is_sensor && !filter.include_sensors) return false;
  if (body.type == BodyType::Static && !filter.include_static) return false;
  return !filter.accept || filter.accept(body.id);
}

Aabb merge_boxes(const Aabb& a, const Aabb& b) {
  return Aabb{glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)};
}

}  // namespace

ShapeDistance shape_distance(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb) {
  return hull_distance(hull_of(a, xa), hull_of(b, xb));
}

int World::overlap_shape(const Shape& shape, const Transform& transform, BodyId* out, int capacity,
                         const QueryFilter& filter) const {
  const char* caller = "World::overlap_shape";
  require_query_shape(shape, transform, caller);
  if (capacity < 0 || (capacity > 0 && out == nullptr)) {
    throw Error("World::overlap_shape: capacity must be >= 0 with a buffer for it");
  }
  const Shape placed = as_placed(shape, transform);
  const Aabb bounds = compute_aabb(placed, transform);
  const WorldState& world = *state_;
  int found = 0;
  int kept = 0;
  world.broad_phase.visit_overlaps(bounds, [&](std::uint32_t slot) {
    const Body& body = world.bodies[slot];
    if (!passes(world, slot, filter) || !body.aabb.overlaps(bounds)) return true;
    // The narrow phase's own test: overlapping shapes give manifold points at margin 0.
    bool overlaps = false;
    for (int i = 0; i < shape_count_of(body) && !overlaps; ++i) {
      overlaps = (layers_of(body, i) & filter.layers) != 0 && (filter.include_sensors || !is_sensor_shape(body, i)) &&
                 collide(placed, transform, shape_of(body, i), shape_transform(body, i)).point_count > 0;
    }
    if (!overlaps) return true;
    ++found;
    // Keep the `capacity` smallest slots, ascending (tree order is not slot order).
    int at = kept;
    while (at > 0 && out[at - 1].index > slot) --at;
    if (at >= capacity) return true;
    const int last = kept < capacity ? kept : capacity - 1;
    for (int i = last; i > at; --i) out[i] = out[i - 1];
    out[at] = body.id;
    if (kept < capacity) ++kept;
    return true;
  });
  return found;
}

std::optional<ShapeCastHit> World::cast_shape(const Shape& shape, const Transform& transform,
                                              vec2 translation, const QueryFilter& filter) const {
  const char* caller = "World::cast_shape";
  require_query_shape(shape, transform, caller);
  require_finite_query(translation, caller, "translation");
  const Shape placed = as_placed(shape, transform);
  const Hull start = hull_of(placed, transform);
  const Aabb start_bounds = compute_aabb(placed, transform);
  const Aabb swept = merge_boxes(start_bounds, Aabb{start_bounds.lower + translation, start_bounds.upper + translation});
  const WorldState& world = *state_;
  const float length = std::sqrt(glm::dot(translation, translation));
  // Conservative advancement along the translation stops this close (metres) to the surface.
  constexpr float touch_tolerance = 1.0e-6f;
  std::optional<ShapeCastHit> best;
  // The first meeting of the moving shape with `target_shape` at `target_at` (a compound body:
  // one of its shapes), in `hit` (all but its body); false when they do not meet.
  auto cast_against = [&](const Shape& target_shape, const Transform& target_at, ShapeCastHit& hit) {
    const Hull target = hull_of(target_shape, target_at);
    if (collide(placed, transform, target_shape, target_at).point_count > 0) {
      // Overlapping at the start.
      hit.fraction = 0.0f;
      hit.point = transform.position;
      hit.normal = length > 0.0f ? -translation / length : vec2(0.0f);
    } else {
      // Advance by distance / closing speed along the closest-points normal: the moving shape
      // cannot cross the separating line through its closest point sooner, so this never
      // passes the first touch, and meets a face head-on in one step.
      float fraction = 0.0f;
      Hull moved = start;
      bool reached = false;
      for (int iteration = 0; iteration < 50; ++iteration) {
        const ShapeDistance distance = hull_distance(moved, target);
        if (distance.distance <= touch_tolerance) {
          // Touching: the closest points of this pose, or (at exactly zero distance, where
          // GJK has no normal) those of the last pose, which the straight move keeps on B.
          if (distance.distance > 0.0f) {
            hit.point = distance.point_b;
            hit.normal = -distance.normal;
          } else if (iteration == 0) {
            hit.point = distance.point_b;
            hit.normal = length > 0.0f ? -translation / length : vec2(0.0f);
          }
          reached = true;
          break;
        }
        const float closing = glm::dot(translation, distance.normal);
        if (!(closing > 0.0f)) break;  // moving away from it: no hit
        fraction += distance.distance / closing;
        if (fraction > 1.0f) break;
        for (int i = 0; i < start.count; ++i) moved.vertices[i] = start.vertices[i] + translation * fraction;
        hit.point = distance.point_b;
        hit.normal = -distance.normal;
      }
      if (!reached) return false;
      hit.fraction = fraction;
    }
    return true;
  };
  world.broad_phase.visit_overlaps(swept, [&](std::uint32_t slot) {
    const Body& body = world.bodies[slot];
    if (!passes(world, slot, filter) || !body.aabb.overlaps(swept)) return true;
    for (int part = 0; part < shape_count_of(body); ++part) {
      if ((layers_of(body, part) & filter.layers) == 0 || (!filter.include_sensors && is_sensor_shape(body, part))) {
        continue;
      }
      const Shape& target_shape = shape_of(body, part);
      const Transform target_at = shape_transform(body, part);
      ShapeCastHit hit;
      if (!cast_against(target_shape, target_at, hit)) continue;
      hit.body = body.id;
      if (!best || hit.fraction < best->fraction ||
          (hit.fraction == best->fraction && slot < best->body.index)) {
        best = hit;
      }
    }
    return true;
  });
  return best;
}

std::optional<RayHit> World::raycast_closest(vec2 origin, vec2 translation, const QueryFilter& filter) const {
  require_finite_query(origin, "World::raycast_closest", "origin");
  require_finite_query(translation, "World::raycast_closest", "translation");
  const WorldState& world = *state_;
  const Aabb swept{glm::min(origin, origin + translation), glm::max(origin, origin + translation)};
  std::optional<RayHit> closest;
  world.broad_phase.visit_overlaps(swept, [&](std::uint32_t slot) {
    if (!passes(world, slot, filter)) return true;
    const Body& body = world.bodies[slot];
    ShapeRayHit shape_hit;
    if (raycast_body(body, origin, translation, filter.layers, filter.include_sensors, &shape_hit) &&
        (!closest || shape_hit.fraction < closest->fraction ||
         (shape_hit.fraction == closest->fraction && slot < closest->body.index))) {
      closest = RayHit{body.id, origin + translation * shape_hit.fraction, shape_hit.normal, shape_hit.fraction};
    }
    return true;
  });
  return closest;
}

}  // namespace impulse2d

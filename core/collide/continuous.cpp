#include "core/collide/continuous.h"

#include "core/collide.h"
#include "core/solver/integrate.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

Aabb merge(const Aabb& a, const Aabb& b) {
  return Aabb{glm::min(a.lower, b.lower), glm::max(a.upper, b.upper)};
}

// The bullet's pose at fraction t of its motion from `start` to `end`.
Transform pose_at(const Transform& start, float start_angle, const Transform& end, float end_angle, float t) {
  const vec2 position = start.position + (end.position - start.position) * t;
  return Transform{position, Rotation::from_angle(start_angle + (end_angle - start_angle) * t)};
}

bool overlaps_any(const Body& bullet, const Transform& pose, const std::vector<Body>& bodies,
                  const std::vector<std::uint32_t>& candidates) {
  for (std::uint32_t index : candidates) {
    const Body& other = bodies[index];
    if (bodies_overlap(bullet, pose, other)) return true;
  }
  return false;
}

}  // namespace

float smallest_extent(const Shape& shape) {
  switch (shape.type()) {
    case ShapeType::Circle: return shape.circle().radius;
    case ShapeType::Box: return std::min(shape.box().half_extents.x, shape.box().half_extents.y);
    case ShapeType::Polygon: {
      float nearest = glm::dot(shape.polygon().normals[0], shape.polygon().vertices[0]);
      for (int i = 1; i < shape.polygon().count; ++i) {
        nearest = std::min(nearest, glm::dot(shape.polygon().normals[i], shape.polygon().vertices[i]));
      }
      return nearest + shape.polygon().rounding;
    }
    case ShapeType::Capsule: return shape.capsule().radius;
    case ShapeType::Segment: return 0.0f;  // never a bullet: segments are not dynamic
  }
  return 0.0f;
}

int BulletSweeper::sweep(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                         const WorldSettings& settings, float dt, BroadPhase& broad_phase) {
  int moved_back = 0;
  bool trees_cover_bodies = false;
  for (std::uint32_t b = 0; b < bodies.size(); ++b) {
    Body& bullet = bodies[b];
    if (!alive[b] || !bullet.is_bullet || bullet.is_sensor || bullet.type != BodyType::Dynamic || !bullet.awake) continue;
    // A compound bullet samples at its thinnest shape with area (its segments have none).
    float thinnest = smallest_extent(shape_of(bullet, 0));
    for (int i = 1; i < shape_count_of(bullet); ++i) {
      const float extent = smallest_extent(shape_of(bullet, i));
      if (extent > 0.0f && (extent < thinnest || !(thinnest > 0.0f))) thinnest = extent;
    }
    const float spacing = 0.5f * thinnest;
    const Transform end = bullet.transform;
    const float end_angle = bullet.angle;
    const bool rotates = effective_inverse_inertia(bullet, settings) != 0.0f;
    const float start_angle = rotates ? end_angle - bullet.angular_velocity * dt : end_angle;
    const Transform start{end.position - bullet.linear_velocity * dt, Rotation::from_angle(start_angle)};
    const float distance = glm::length(end.position - start.position);
    if (!(distance > spacing) || !(spacing > 0.0f)) continue;

    const Aabb swept = merge(body_aabb(bullet, start), body_aabb(bullet, end));
    if (!trees_cover_bodies) {
      // Bodies moved since the trees last covered them; bullets are never candidates.
      for (std::uint32_t o = 0; o < bodies.size(); ++o) {
        if (alive[o] && !bodies[o].is_bullet) {
          broad_phase.cover(o, body_aabb(bodies[o]));
        }
      }
      trees_cover_bodies = true;
    }
    broad_phase.query(swept, nearby_);
    candidates_.clear();
    for (const std::uint32_t o : nearby_) {
      const Body& other = bodies[o];
      if (o == b || !alive[o] || other.is_bullet || other.is_sensor) continue;
      if ((other.collision_layers & bullet.collision_layers) == 0) continue;
      if (!body_aabb(other).overlaps(swept)) continue;
      // Already touching at the start: the ordinary contact handles that pair.
      if (bodies_overlap(bullet, start, other)) continue;
      candidates_.push_back(o);
    }
    if (candidates_.empty()) continue;

    const int samples = static_cast<int>(std::ceil(distance / spacing));
    float free_t = 0.0f;
    for (int k = 1; k <= samples; ++k) {
      const float t = static_cast<float>(k) / static_cast<float>(samples);
      if (!overlaps_any(bullet, pose_at(start, start_angle, end, end_angle, t), bodies, candidates_)) {
        free_t = t;
        continue;
      }
      float hit_t = t;
      for (int i = 0; i < 10; ++i) {  // bisect the time of impact to 1/1024 of a sample
        const float middle = 0.5f * (free_t + hit_t);
        if (overlaps_any(bullet, pose_at(start, start_angle, end, end_angle, middle), bodies, candidates_)) {
          hit_t = middle;
        } else {
          free_t = middle;
        }
      }
      if (hit_t < 1.0f) {
        bullet.transform = pose_at(start, start_angle, end, end_angle, hit_t);
        bullet.angle = start_angle + (end_angle - start_angle) * hit_t;
        ++moved_back;
      }
      break;
    }
  }
  return moved_back;
}

}  // namespace impulse2d

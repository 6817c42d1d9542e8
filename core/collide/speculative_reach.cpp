#include "core/collide/speculative_reach.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

}  // namespace

float rotation_reach(const Shape& shape) {
  switch (shape.type()) {
    case ShapeType::Circle:
    case ShapeType::Box:
      return 0.0f;
    case ShapeType::Polygon:
      return polygon_radius(shape.polygon());
    case ShapeType::Capsule:
      return std::sqrt(std::max(length_squared(shape.capsule().center1),
                                length_squared(shape.capsule().center2)));
    case ShapeType::Segment:
      return std::sqrt(std::max(length_squared(shape.segment().point1),
                                length_squared(shape.segment().point2)));
  }
  return 0.0f;
}

void compute_speculative_reach(const std::vector<Body>& bodies,
                               const std::vector<std::uint8_t>& alive,
                               const WorldSettings& settings, float dt,
                               std::vector<float>& reach, WorkerPool* pool) {
  reach.assign(bodies.size(), 0.0f);
  if (!(settings.speculative_margin > 0.0f)) return;
  const float gravity = std::sqrt(length_squared(settings.gravity));
  parallel_for(pool, bodies.size(), 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Body& body = bodies[i];
      if (!alive[i] || body.type == BodyType::Static || !body.awake) continue;
      const float gravity_speed =
          body.type == BodyType::Dynamic ? gravity * std::fabs(body.gravity_scale) * dt : 0.0f;
      const float speed = std::sqrt(length_squared(body.linear_velocity)) + gravity_speed;
      const float turning =
          settings.enable_rotation
              ? std::fabs(body.angular_velocity) * (body.compound ? body.extent : rotation_reach(body.shape))
              : 0.0f;
      reach[i] = (speed + turning) * dt;
    }
  });
}

void compute_speculative_bounds(const std::vector<Body>& bodies,
                                const std::vector<std::uint8_t>& alive,
                                const std::vector<float>& reach, float margin,
                                std::vector<Aabb>& bounds, WorkerPool* pool) {
  bounds.resize(bodies.size());
  parallel_for(pool, bodies.size(), 256, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (!alive[i]) continue;
      const vec2 grow(0.5f * margin + reach[i]);
      bounds[i] = Aabb{bodies[i].aabb.lower - grow, bodies[i].aabb.upper + grow};
    }
  });
}

}  // namespace impulse2d

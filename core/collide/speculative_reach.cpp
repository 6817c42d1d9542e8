#include "core/collide/speculative_reach.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

// Farthest distance (m) of a rotating shape's surface from the centre of mass; 0 for a circle
// (turning about its centre moves no surface point) and for a box (never rotates).
float rotation_radius(const Shape& shape) {
  return shape.type() == ShapeType::Polygon ? polygon_radius(shape.polygon()) : 0.0f;
}

}  // namespace

void compute_speculative_reach(const std::vector<Body>& bodies,
                               const std::vector<std::uint8_t>& alive,
                               const WorldSettings& settings, float dt,
                               std::vector<float>& reach) {
  reach.assign(bodies.size(), 0.0f);
  if (!(settings.speculative_margin > 0.0f)) return;
  const float gravity = std::sqrt(length_squared(settings.gravity));
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Body& body = bodies[i];
    if (!alive[i] || body.type == BodyType::Static || !body.awake) continue;
    const float gravity_speed =
        body.type == BodyType::Dynamic ? gravity * std::fabs(body.gravity_scale) * dt : 0.0f;
    const float speed = std::sqrt(length_squared(body.linear_velocity)) + gravity_speed;
    const float turning = settings.enable_rotation
                              ? std::fabs(body.angular_velocity) * rotation_radius(body.shape)
                              : 0.0f;
    reach[i] = (speed + turning) * dt;
  }
}

void compute_speculative_bounds(const std::vector<Body>& bodies,
                                const std::vector<std::uint8_t>& alive,
                                const std::vector<float>& reach, float margin,
                                std::vector<Aabb>& bounds) {
  bounds.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (!alive[i]) continue;
    const vec2 grow(0.5f * margin + reach[i]);
    bounds[i] = Aabb{bodies[i].aabb.lower - grow, bodies[i].aabb.upper + grow};
  }
}

}  // namespace impulse2d

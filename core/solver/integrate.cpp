#include "core/solver/integrate.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

float effective_inverse_inertia(const Body& body, const WorldSettings& settings) {
  if (!settings.enable_rotation || body.fixed_rotation || body.shape.type() == ShapeType::Box) {
    return 0.0f;
  }
  return body.inverse_inertia;
}

vec2 clamp_speed(vec2 velocity, float speed_squared, float max_speed) {
  if (std::isfinite(speed_squared)) return velocity * (max_speed / std::sqrt(speed_squared));
  // The square overflowed (a speed above ~1.8e19 m/s): scale down first, or the factor
  // max_speed / inf would stop the body instead of clamping it.
  const float largest = std::max(std::fabs(velocity.x), std::fabs(velocity.y));
  if (!std::isfinite(largest)) return velocity;  // non-finite: the world reports the body
  const vec2 direction = velocity / largest;
  return direction * (max_speed / std::sqrt(length_squared(direction)));
}

namespace {
// Body slots a worker takes at least at a time.
constexpr std::size_t min_bodies_per_chunk = 128;
}  // namespace

void integrate_velocities(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                          const WorldSettings& settings, float dt, WorkerPool* pool) {
  const float max_speed_squared = settings.max_linear_speed * settings.max_linear_speed;
  parallel_for(pool, bodies.size(), min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Body& body = bodies[i];
      if (!alive[i] || body.type != BodyType::Dynamic || !body.awake) continue;
      const vec2 acceleration = body.force * body.inverse_mass + settings.gravity * body.gravity_scale;
      body.linear_velocity += acceleration * dt;
      body.angular_velocity += body.torque * effective_inverse_inertia(body, settings) * dt;
      // Implicit damping: stable for any dt (Box2D's form).
      body.linear_velocity *= 1.0f / (1.0f + dt * body.linear_damping);
      body.angular_velocity *= 1.0f / (1.0f + dt * body.angular_damping);
      if (effective_inverse_inertia(body, settings) == 0.0f) body.angular_velocity = 0.0f;
      const float speed_squared = length_squared(body.linear_velocity);
      if (speed_squared > max_speed_squared) {
        body.linear_velocity = clamp_speed(body.linear_velocity, speed_squared,
                                           settings.max_linear_speed);
      }
    }
  });
}

void integrate_positions(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                         const WorldSettings& settings, float dt, WorkerPool* pool) {
  parallel_for(pool, bodies.size(), min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      Body& body = bodies[i];
      if (!alive[i] || !is_integrated(body)) continue;
      body.transform.position += body.linear_velocity * dt;
      if (body.type == BodyType::Dynamic && effective_inverse_inertia(body, settings) == 0.0f) {
        continue;  // no rotation modelled for this body
      }
      if (body.angular_velocity != 0.0f) {
        body.angle += body.angular_velocity * dt;
        body.transform.rotation = Rotation::from_angle(body.angle);
      }
    }
  });
}

void update_bounds(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                   WorkerPool* pool) {
  parallel_for(pool, bodies.size(), min_bodies_per_chunk, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (alive[i]) bodies[i].aabb = body_aabb(bodies[i]);
    }
  });
}

}  // namespace impulse2d

#pragma once
/// @file integrate.h
/// Moves bodies through time: velocities from forces and gravity, positions from velocities.

#include "core/solver/body_shapes.h"
#include "core/settings.h"
#include "core/solver/worker_pool.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// True when the body is moved by the integrator this step (awake and not static).
inline bool is_integrated(const Body& body) {
  return body.type != BodyType::Static && body.awake;
}

/// Effective inverse inertia of a body under the world's settings: 0 when rotation is
/// disabled for the scene, fixed for the body, or the shape is an axis-aligned box.
float effective_inverse_inertia(const Body& body, const WorldSettings& settings);

/// `velocity` scaled to length `max_speed`, given its squared length `speed_squared` (which
/// may have overflowed to infinity: the direction is kept all the same). A non-finite
/// velocity is returned unchanged.
vec2 clamp_speed(vec2 velocity, float speed_squared, float max_speed);

/// v += (F / m + g * gravity_scale) dt, w += T / I dt, then damping and the speed clamp, for
/// every awake dynamic body. Kinematic bodies keep their velocity. With a `pool`, the bodies
/// are shared among its workers (each body is its own work: the same bits).
void integrate_velocities(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                          const WorldSettings& settings, float dt, WorkerPool* pool = nullptr);

/// x += v dt, angle += w dt for every awake non-static body; refreshes the transform (with a
/// `pool`, as `integrate_velocities`).
void integrate_positions(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                         const WorldSettings& settings, float dt, WorkerPool* pool = nullptr);

/// Recomputes the world bounds of every living body (with a `pool`, shared among its workers).
void update_bounds(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                   WorkerPool* pool = nullptr);

}  // namespace impulse2d

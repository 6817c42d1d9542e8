#pragma once
/// @file solver_bodies.h
/// The soft step's bodies in compact form (issue 13's hot/cold split): a 32-byte `SolverBody`
/// per body slot (velocity, pose, angle) and a 24-byte `BodyIntegration` (what integrating it
/// needs), filled from the world's `Body`s once per step and written back once at its end.
/// The sub-steps integrate and solve on these arrays only, so a sub-step reads ~56 bytes per
/// body instead of the ~340 of a `Body`. The arithmetic is `integrate.h`'s, operation for
/// operation, so the results are bit-identical to integrating the `Body`s themselves.

#include "core/contact.h"
#include "core/solver/body_state.h"
#include "core/settings.h"
#include "core/solver/solver_body.h"
#include "core/solver/worker_pool.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// What integrating one body slot over a sub-step needs, resolved once per step.
struct BodyIntegration {
  float acceleration_x = 0.0f;        ///< m/s^2: force / mass + gravity * gravity_scale
  float acceleration_y = 0.0f;        ///< m/s^2
  float angular_acceleration = 0.0f;  ///< rad/s^2: torque * effective inverse inertia
  float linear_damping = 0.0f;        ///< 1/s
  float angular_damping = 0.0f;       ///< 1/s
  /// `flag_*` bits: which of the sub-step's updates apply to this slot.
  std::uint32_t flags = 0;
};

/// The velocity and pose of every body slot for one step, and their integration.
class SolverBodies {
 public:
  /// Slot is moved by its velocity (alive, awake, not static).
  static constexpr std::uint32_t flag_moves = 1u;
  /// Slot's velocity is integrated (alive, awake, dynamic).
  static constexpr std::uint32_t flag_accelerates = 2u;
  /// Slot's velocity is the contacts' to change (alive and dynamic, awake or not), so it is
  /// written back.
  static constexpr std::uint32_t flag_solved = 8u;
  /// Slot turns: its angle follows its angular velocity (not a dynamic body whose effective
  /// inverse inertia is 0; see `effective_inverse_inertia`).
  static constexpr std::uint32_t flag_turns = 4u;

  /// Loads every slot's state from `bodies` and resolves its integration for this step's
  /// forces and the world's settings (gravity, rotation switch, speed limit); with a `pool`,
  /// the slots shared among its workers.
  void begin_step(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                  const WorldSettings& settings, WorkerPool* pool = nullptr);
  /// `integrate_velocities` of integrate.h on the compact state, over `dt` seconds (the
  /// slots shared among `pool`'s workers when there is one: each slot is its own work).
  void integrate_velocities(float dt, WorkerPool* pool = nullptr);
  /// `integrate_positions` of integrate.h on the compact state, over `dt` seconds (with a
  /// `pool`, as `integrate_velocities`).
  void integrate_positions(float dt, WorkerPool* pool = nullptr);
  /// `integrate_velocities` over the `count` slots listed at `slots` only, on this thread.
  void integrate_velocities(float dt, const std::uint32_t* slots, std::size_t count);
  /// `integrate_positions` over the `count` slots listed at `slots` only, on this thread.
  void integrate_positions(float dt, const std::uint32_t* slots, std::size_t count);
  /// Writes the velocity back to every slot the contacts may change, pose and angle to every
  /// slot that moves (with a `pool`, the slots shared among its workers).
  void store(std::vector<Body>& bodies, WorkerPool* pool = nullptr) const;
  /// Reads what `store` writes back in (after a stage that works
  /// on the `Body`s changed them: bounces, bullet sweeps).
  void load(const std::vector<Body>& bodies);
  /// `store` for the slots of the bodies of the contacts listed in `listed` (indices into
  /// `contacts`) only, on this thread (a slot named twice is written twice, alike).
  void store_bodies_of(std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                       const std::vector<std::uint32_t>& listed) const;
  /// `load` for the same slots only.
  void load_bodies_of(const std::vector<Body>& bodies, const std::vector<Contact>& contacts,
                      const std::vector<std::uint32_t>& listed);
  /// True when some moving body is a bullet (the continuous sweep has work this step).
  bool has_bullets() const { return has_bullets_; }
  /// The states, one per body slot, for the contact solver.
  SolverBody* states() { return states_.data(); }

 private:
  // Over the slots slots[0] .. slots[slots.size() - 1] (a range of slots or a list of them).
  template <class Slots>
  void integrate_velocities_of(float dt, Slots slots);
  template <class Slots>
  void integrate_positions_of(float dt, Slots slots);
  // `store` and `load` of one slot.
  void store_slot(std::size_t slot, Body& body) const;
  void load_slot(std::size_t slot, const Body& body);

  std::vector<SolverBody> states_;
  std::vector<BodyIntegration> integration_;
  float max_linear_speed_ = 0.0f;  // m/s
  bool has_bullets_ = false;
};

}  // namespace impulse2d

#pragma once
/// @file solver_context.h
/// The settings a solver method reads, resolved once per step from `WorldSettings` so the
/// inner loops never re-read or re-derive them.

#include "core/settings.h"
#include "core/solver/contact_touch.h"
#include "core/solver/softness.h"

namespace impulse2d {

/// Everything a solver method needs about the step, derived once per step.
struct SolverContext {
  float time_step = 0.0f;          ///< seconds per step
  vec2 gravity{0.0f, 0.0f};        ///< m/s^2
  bool rotation = true;            ///< false: no body rotates (angular terms skipped)
  int substeps = 1;                ///< sub-steps per step
  float substep = 0.0f;            ///< seconds per sub-step (time_step / substeps)
  int velocity_iterations = 0;     ///< passes over all contacts per (sub-)step
  bool warm_starting = true;       ///< apply last step's accumulated impulses first
  bool block_solver = true;        ///< 2x2 normal block for two-point manifolds
  bool shock_propagation = true;   ///< a ground-up pass with lower bodies held fixed
  bool friction = true;            ///< tangent impulses on
  bool restitution = true;         ///< bounces on
  float restitution_threshold = 0.0f;  ///< m/s: slower impacts do not bounce
  float slop = 0.0f;               ///< m: overlap position correction leaves alone
  bool explicit_euler = false;     ///< positions move before velocities change
  /// Soft contact between two moving bodies over one sub-step (SoftStep).
  Softness dynamic_softness;
  /// Soft contact against a static or kinematic body: twice as stiff (SoftStep).
  Softness static_softness;
  /// The rigid parts of joints: a spring of twice the contact hertz, damping ratio 2, over one
  /// sub-step (Box2D v3's joint softness); the relax pass drops its bias.
  Softness joint_softness;
  float push_max_speed = 0.0f;     ///< m/s: fastest soft push-out (SoftStep)
  /// m/s: approach speed above which a point is being caught, not resting: twice what gravity
  /// adds in a step (`ContactPoint::caught`).
  float catch_speed = 0.0f;
  /// Impulse intervals one prepare covers, for the start-of-step friction check
  /// (`static_friction_cannot_stop`): the soft step's sub-steps, 1 for the accumulated solver,
  /// 0 (no check) for the per-iteration solver, which decides the state in every iteration,
  /// and with friction off.
  float friction_intervals = 0.0f;
  int solver_lanes = 0;            ///< contacts solved side by side, 0: widest (SoftStep)
  /// The bodies' free velocities over the step when contact events are on (else null):
  /// `prepare_contact` then records `Contact::touching`.
  FreeVelocities touch_velocities;
};

/// Resolves `settings` for one step.
SolverContext resolve_solver_context(const WorldSettings& settings);

}  // namespace impulse2d

#include "core/solver/solver_context.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

SolverContext resolve_solver_context(const WorldSettings& settings) {
  SolverContext context;
  context.time_step = settings.time_step;
  context.gravity = settings.gravity;
  context.rotation = settings.enable_rotation;
  context.substeps = settings.substeps;
  context.substep = settings.time_step / static_cast<float>(settings.substeps);
  context.velocity_iterations = settings.velocity_iterations;
  context.warm_starting = settings.warm_starting;
  context.block_solver = settings.block_solver;
  context.shock_propagation = settings.shock_propagation;
  context.friction = settings.enable_friction;
  context.restitution = settings.enable_restitution;
  context.restitution_threshold = settings.restitution_threshold;
  context.slop = settings.slop;
  context.explicit_euler = settings.integrator == Integrator::ExplicitEuler;
  // A spring stiffer than a quarter of the sub-step rate would be under-resolved in time.
  const float hertz = std::min(settings.contact_hertz, 0.25f / context.substep);
  context.dynamic_softness = make_soft(hertz, settings.contact_damping_ratio, context.substep);
  context.static_softness = make_soft(2.0f * hertz, settings.contact_damping_ratio, context.substep);
  // Joints' rigid parts: four times the contact's stiffness, at most half the sub-step rate
  // (120 Hz at the soft step's default 1/240 s sub-steps; 30 Hz for the one-step methods, whose
  // contact hertz is capped at 15). A soft rigid part is a spring of m_eff (2 pi f)^2, so a
  // load F stretches it F / (m_eff (2 pi f)^2): a 20-link chain's top joint 0.66 mm at rest at
  // 120 Hz (2.6 mm at Box2D v3's 60 Hz). Stiffer than half the sub-step rate is unstable; at it,
  // stable with the soft step's joint passes (soft_step_solver.cpp).
  const float joint_hertz = std::min(4.0f * hertz, 0.5f / context.substep);
  context.joint_softness = make_soft(joint_hertz, 2.0f, context.substep);
  context.push_max_speed = settings.contact_push_max_speed;
  context.solver_lanes = settings.solver_lanes;
  context.catch_speed = 2.0f * std::sqrt(length_squared(settings.gravity)) * settings.time_step;
  if (settings.enable_friction && settings.solver != SolverMethod::PerIteration) {
    context.friction_intervals =
        settings.solver == SolverMethod::SoftStep ? static_cast<float>(settings.substeps) : 1.0f;
  }
  return context;
}

}  // namespace impulse2d

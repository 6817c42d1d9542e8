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
  context.joint_softness = make_soft(2.0f * hertz, 2.0f, context.substep);
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

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
  // Joints' rigid parts. A soft rigid part is a spring of m_eff (2 pi f)^2, so a load F
  // stretches it F / (m_eff (2 pi f)^2). The soft step, whose joints get several passes
  // (soft_step_solver.cpp), makes them four times as stiff as the contacts, at most half the
  // sub-step rate (120 Hz at its 1/240 s sub-steps: a 20-link chain's top joint 0.66 mm at
  // rest, 2.6 mm at Box2D v3's 60 Hz); stiffer than that is unstable. The other methods solve
  // joints once a pass and keep Box2D v3's twice the contact hertz (30 Hz at one step a frame;
  // at 120 Hz with four sub-steps of two passes a chain under a 15:1 load already opens 1 cm).
  const float joint_hertz = settings.solver == SolverMethod::SoftStep
                                ? std::min(4.0f * hertz, 0.5f / context.substep)
                                : 2.0f * hertz;
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

#pragma once
/// @file soft_step_solver.h
/// `SolverMethod::SoftStep`: Box2D v3's "soft step" (collide once per step; per sub-step
/// integrate velocities, warm start, solve soft contacts, integrate positions, relax), with
/// speculative contacts, bounces timed at impact within the sub-step where they happen, and
/// Coulomb's static/dynamic switch per contact at the end of the step.

#include "core/solver/step_solver.h"

#include "core/solver/solver_bodies.h"
#include "core/solver/wide_contact_solver.h"

namespace impulse2d {

/// Collides once with a speculative margin covering the whole step, then runs `substeps`
/// sub-steps of `velocity_iterations` soft passes and as many relax passes each. Position
/// correction, `block_solver` and `integrator` (always semi-implicit) are not used: the soft
/// push-out replaces position correction.
class SoftStepSolver final : public StepSolver {
 public:
  void step(SolverStages& stages, const SolverContext& context) const override;

 private:
  // The sub-steps when the wide solver laid its blocks out by island batch (`batched`): all
  // sub-steps of one batch, then the next.
  void solve_island_batches(SolverStages& stages, const SolverContext& context,
                            WideContactSolver& wide, SolverBodies& states) const;
  // The sub-steps over the whole world, pass by pass (joints, bounces and the shock pass).
  void solve_pass_by_pass(SolverStages& stages, const SolverContext& context,
                          WideContactSolver& wide, bool may_bounce, bool shock) const;
  // After the sub-steps: the bodies written back, bullets swept, impulses stored and
  // friction switched.
  void finish_step(SolverStages& stages, const SolverContext& context,
                   WideContactSolver& wide) const;
};

}  // namespace impulse2d

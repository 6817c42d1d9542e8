#pragma once
/// @file soft_step_solver.h
/// `SolverMethod::SoftStep`: Box2D v3's "soft step" (collide once per step; per sub-step
/// integrate velocities, warm start, solve soft contacts, integrate positions, relax), with
/// speculative contacts, bounces timed at impact within the sub-step where they happen, and
/// Coulomb's static/dynamic switch per contact at the end of the step.

#include "core/solver/step_solver.h"

namespace impulse2d {

/// Collides once with a speculative margin covering the whole step, then runs `substeps`
/// sub-steps of `velocity_iterations` soft passes and as many relax passes each. Position
/// correction, `block_solver` and `integrator` (always semi-implicit) are not used: the soft
/// push-out replaces position correction.
class SoftStepSolver final : public StepSolver {
 public:
  void step(SolverStages& stages, const SolverContext& context) const override;
};

}  // namespace impulse2d

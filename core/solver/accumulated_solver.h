#pragma once
/// @file accumulated_solver.h
/// `SolverMethod::Accumulated`: sequential impulses with accumulated, clamped normal
/// and friction impulses per point, warm-started from the previous step (Box2D v2's form),
/// with speculative targets, bounces timed at impact, Coulomb's static/dynamic switch per
/// contact, and position correction after each (sub-)step.

#include "core/solver/step_solver.h"

namespace impulse2d {

/// Per (sub-)step: collide, prepare, integrate velocities, plan targets, warm start,
/// `velocity_iterations` passes (the normal impulses: the 2x2 block for two-point manifolds
/// when `block_solver` is on; then friction), switch friction state, integrate
/// positions, bounce, correct positions.
class AccumulatedSolver final : public StepSolver {
 public:
  void step(SolverStages& stages, const SolverContext& context) const override;
};

}  // namespace impulse2d

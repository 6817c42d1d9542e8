#pragma once
/// @file per_iteration_solver.h
/// `SolverMethod::PerIteration`: the tutorial's form. Each iteration computes a fresh impulse
/// per contact point from the current relative velocity and applies it (no memory between
/// iterations or steps); friction uses the static/dynamic Coulomb test against that
/// iteration's normal impulse. Speculative targets and bounces as in `contact_bounce.h`.

#include "core/solver/step_solver.h"

namespace impulse2d {

/// Per (sub-)step: collide, prepare, integrate velocities, plan targets, `velocity_iterations`
/// passes of j = -(vn - target) / K per approaching point followed by its friction (jt if
/// |jt| < j mu_s, else -j mu_d), integrate positions, bounce, correct positions.
class PerIterationSolver final : public StepSolver {
 public:
  void step(SolverStages& stages, const SolverContext& context) const override;
};

}  // namespace impulse2d

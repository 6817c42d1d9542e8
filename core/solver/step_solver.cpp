#include "core/solver/step_solver.h"

#include "core/solver/accumulated_solver.h"
#include "core/error.h"
#include "core/solver/per_iteration_solver.h"
#include "core/solver/soft_step_solver.h"

namespace impulse2d {

std::shared_ptr<const StepSolver> make_step_solver(SolverMethod method) {
  switch (method) {
    case SolverMethod::PerIteration: return std::make_shared<PerIterationSolver>();
    case SolverMethod::Accumulated: return std::make_shared<AccumulatedSolver>();
    case SolverMethod::SoftStep: return std::make_shared<SoftStepSolver>();
  }
  throw Error("make_step_solver: unknown solver method");
}

}  // namespace impulse2d

#include "core/settings.h"

#include "core/error.h"
#include "core/solver/wide_contact_solver.h"

#include <cmath>
#include <string>
#include <utility>

namespace impulse2d {

const char* solver_name(SolverMethod method) {
  switch (method) {
    case SolverMethod::PerIteration: return "per_iteration";
    case SolverMethod::Accumulated: return "accumulated";
    case SolverMethod::SoftStep: return "soft_step";
  }
  return "?";
}

const std::vector<SolverMethod>& solver_methods() {
  static const std::vector<SolverMethod> methods{SolverMethod::PerIteration,
                                                 SolverMethod::Accumulated, SolverMethod::SoftStep};
  return methods;
}

std::optional<SolverMethod> retired_solver_name(const std::string& name) {
  static const std::pair<const char*, SolverMethod> retired[] = {
      {"iter", SolverMethod::PerIteration},
      {"PerIteration", SolverMethod::PerIteration},
      {"acc", SolverMethod::Accumulated},
      {"Accumulated", SolverMethod::Accumulated},
      {"AccumulatedImpulses", SolverMethod::Accumulated},
      {"accumulated_impulses", SolverMethod::Accumulated},
      {"soft", SolverMethod::SoftStep},
      {"SoftStep", SolverMethod::SoftStep},
  };
  for (const auto& [spelling, method] : retired) {
    if (name == spelling) return method;
  }
  return std::nullopt;
}

WorldSettings settings_for(SolverMethod method) {
  WorldSettings settings;
  settings.solver = method;
  if (method != SolverMethod::SoftStep) {
    settings.substeps = 1;
    settings.velocity_iterations = 16;
  }
  return settings;
}

void validate_settings(const WorldSettings& s) {
  auto require = [](bool ok, const char* field, const char* reason) {
    if (!ok) throw Error(std::string("WorldSettings.") + field + ": " + reason);
  };
  auto finite = [](float value) { return std::isfinite(value); };
  require(is_finite(s.gravity), "gravity", "must be finite");
  require(finite(s.time_step) && s.time_step > 0.0f, "time_step", "must be finite and > 0");
  require(s.substeps >= 1 && s.substeps <= 64, "substeps", "must be in 1..64");
  require(s.velocity_iterations >= 0 && s.velocity_iterations <= 1000, "velocity_iterations",
          "must be in 0..1000");
  require(s.solver_lanes == 0 || s.solver_lanes == 4 || s.solver_lanes == 8, "solver_lanes",
          "must be 0 (widest this CPU runs), 4 or 8");
  require(s.solver_lanes != 8 || WideContactSolver::widest_lanes() == 8, "solver_lanes",
          "8 lanes need AVX2, which this CPU lacks: use 0 or 4");
  require(s.position_iterations >= 0 && s.position_iterations <= 1000, "position_iterations",
          "must be in 0..1000");
  require(finite(s.speculative_margin) && s.speculative_margin >= 0.0f, "speculative_margin",
          "must be finite and >= 0");
  require(finite(s.contact_recycle_distance) && s.contact_recycle_distance >= 0.0f,
          "contact_recycle_distance", "must be finite and >= 0");
  require(finite(s.correction_percent) && s.correction_percent >= 0.0f &&
              s.correction_percent <= 1.0f,
          "correction_percent", "must be in [0, 1]");
  require(finite(s.slop) && s.slop >= 0.0f, "slop", "must be finite and >= 0");
  require(finite(s.max_correction) && s.max_correction > 0.0f, "max_correction",
          "must be finite and > 0");
  require(finite(s.contact_hertz) && s.contact_hertz > 0.0f, "contact_hertz",
          "must be finite and > 0");
  require(finite(s.contact_damping_ratio) && s.contact_damping_ratio >= 0.0f,
          "contact_damping_ratio", "must be finite and >= 0");
  require(finite(s.contact_push_max_speed) && s.contact_push_max_speed >= 0.0f,
          "contact_push_max_speed", "must be finite and >= 0");
  require(finite(s.restitution_threshold) && s.restitution_threshold >= 0.0f,
          "restitution_threshold", "must be finite and >= 0");
  require(finite(s.sleep_linear_speed) && s.sleep_linear_speed >= 0.0f, "sleep_linear_speed",
          "must be finite and >= 0");
  require(finite(s.sleep_angular_speed) && s.sleep_angular_speed >= 0.0f, "sleep_angular_speed",
          "must be finite and >= 0");
  require(finite(s.time_to_sleep) && s.time_to_sleep >= 0.0f, "time_to_sleep",
          "must be finite and >= 0");
  require(finite(s.max_linear_speed) && s.max_linear_speed > 0.0f, "max_linear_speed",
          "must be finite and > 0");
  require(s.worker_count >= 1 && s.worker_count <= 64, "worker_count", "must be in 1..64");
  require(s.task_system.enqueue == nullptr || s.task_system.finish != nullptr,
          "task_system.finish", "must be set when task_system.enqueue is (it waits for the tasks)");
  require(s.task_system.finish == nullptr || s.task_system.enqueue != nullptr,
          "task_system.enqueue", "must be set when task_system.finish is (null means the world's own workers)");
  require(s.task_system.user_context == nullptr || s.task_system.enqueue != nullptr,
          "task_system.user_context", "is set but task_system.enqueue is null (no task system would see it)");
}

}  // namespace impulse2d

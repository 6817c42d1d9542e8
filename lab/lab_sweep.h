#pragma once
/// @file lab_sweep.h
/// The method sweep: every scenario run by every method (and the peers), cost as the median of
/// repeats interleaved in one run (repeat 1 of every configuration, then repeat 2 of every
/// configuration, ...), so a load spike on a shared machine touches every method alike.

#include <cstdint>
#include <functional>
#include <vector>

#include "lab/lab_result.h"
#include "lab/lab_scenario.h"
#include "lab/lab_simulation.h"

namespace impulse2d::lab {

/// What one run of a scenario measured.
struct RunMeasurement {
  std::int64_t steps = 0;          ///< steps taken
  int bodies = 0;                  ///< bodies in the scene
  double step_seconds = 0.0;       ///< wall-clock seconds spent in the engine's step
  std::uint64_t instructions = 0;  ///< user-space instructions in the steps (0: not counted)
  double error = 0.0;              ///< the metric's error (when observed)
  bool diverged = false;           ///< the engine reported non-finite bodies
  unsigned long long hash = 0;     ///< state hash at the end
};

/// Steps `simulation` through `scenario.duration` seconds. With `observe`, the metric follows
/// every step (and its time is not counted); without, only the steps run, timed as a whole and
/// counted in instructions when `count_instructions`.
RunMeasurement run_scenario(const LabScenario& scenario, LabSimulation& simulation, bool observe,
                            bool count_instructions);

/// How to sweep.
struct SweepOptions {
  bool quick = false;        ///< the smaller method space of `method_space(true)`
  int repeats = 3;           ///< timed runs per configuration (>= 1); the first also measures error
  int shard_index = 0;       ///< run jobs with job % shard_count == shard_index
  int shard_count = 1;       ///< number of shards (>= 1)
  bool peers = true;         ///< also run the peers that are compiled in
  bool count_instructions = true;  ///< count instructions when the kernel allows it
  /// Called after each run with (runs done, runs in total); may be empty.
  std::function<void(std::int64_t, std::int64_t)> progress;
};

/// Runs the sweep and returns one result per configuration of this shard, fronts marked.
/// Throws `demos::Interrupted` when SIGINT, SIGTERM or SIGHUP arrives.
std::vector<LabResult> run_sweep(const std::vector<LabScenario>& scenarios,
                                 const SweepOptions& options);

/// The configurations the sweep runs for `scenario`: `method_space(quick)` then the peers that
/// are compiled in at the scenario's own time step.
std::vector<LabMethod> sweep_methods(const LabScenario& scenario, bool quick, bool peers);

}  // namespace impulse2d::lab

#pragma once
/// @file lab_result.h
/// One row of the lab's CSV: a scenario run by a method, its cost and its error.

#include <cstdint>
#include <string>
#include <vector>

#include "lab/lab_method.h"

namespace impulse2d::lab {

/// The outcome of one configuration on one scenario.
struct LabResult {
  std::int64_t job = 0;       ///< index of (scenario, method) in the full sweep (shards keep it)
  std::string scenario;       ///< scenario name
  LabMethod method;           ///< what ran it
  std::int64_t steps = 0;     ///< steps per run
  int bodies = 0;             ///< bodies in the scene
  int repeats = 0;            ///< timed runs (the cost is their median)
  double ns_per_step = 0.0;   ///< median wall-clock time of one step, ns
  double ns_per_step_body = 0.0;       ///< ns_per_step / bodies
  double us_per_simulated_second = 0.0;  ///< ns_per_step x steps per second / 1000: the chart's cost
  double instructions_per_step = 0.0;  ///< median user-space instructions per step (0: not counted)
  double error = 0.0;         ///< the metric's error (infinity: the run diverged or failed)
  std::string unit;           ///< of `error` and `threshold`
  double threshold = 0.0;     ///< pass iff error <= threshold
  bool pass = false;          ///< error <= threshold, finite, deterministic
  std::string failure;        ///< why it failed ("" when it passed)
  bool pareto = false;        ///< on the scenario's Pareto front (no other point cheaper and better)
  /// The cheapest impulse2d method that passes on this scenario with the default mixing rules.
  bool recommended = false;
};

/// Marks `pareto` and `recommended` per scenario over `results` (cost:
/// `us_per_simulated_second`; error: `error`).
void mark_fronts(std::vector<LabResult>& results);

/// The CSV header line (no newline).
std::string csv_header();
/// One CSV line for `result` (no newline); floats with 9 significant digits.
std::string csv_line(const LabResult& result);
/// Parses CSV text written by `csv_line` under `csv_header`. Throws `demos::UsageError`
/// "<file>:<line>: <reason>".
std::vector<LabResult> parse_csv(const std::string& text, const std::string& file);

}  // namespace impulse2d::lab

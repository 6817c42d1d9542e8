#pragma once
/// @file work_budget.h
/// What `lab` and `tune` are about to do, estimated before they start (simulation runs, steps
/// and, from a short timed probe, minutes on this machine), and the bound above which they
/// refuse to start without `--force`.

#include <cstdint>
#include <string>

namespace impulse2d::lab {

/// The work of one command, estimated before it starts.
struct WorkEstimate {
  std::int64_t runs = 0;   ///< simulation runs
  std::int64_t steps = 0;  ///< steps over every run (sub-steps not counted)
  double seconds = 0.0;    ///< wall-clock estimate on this machine, s
};

/// Most runs `lab` starts without `--force` (the default full lab is about 3,800).
constexpr std::int64_t max_lab_runs = 20000;
/// Most steps `tune` takes without `--force` (a 10 s scene at 1/60 s is about 200,000).
constexpr std::int64_t max_tune_steps = 20000000;

/// `value` with thousands separated by commas: 121600 -> "121,600".
std::string grouped(std::int64_t value);

/// "121,600 runs, 3,040,000 steps (about 25 min on this machine)".
std::string describe_work(const WorkEstimate& estimate);

/// Throws `demos::UsageError` "<command>: <describe_work> exceeds the bound of <bound> <unit>
/// without --force (<smaller> make it smaller)" when `amount` (the estimate's runs or steps)
/// is above `bound` and not `force`; `smaller` names the options that shrink the work.
void check_budget(const std::string& command, const WorkEstimate& estimate, std::int64_t amount,
                  std::int64_t bound, const std::string& unit, bool force,
                  const std::string& smaller);

}  // namespace impulse2d::lab

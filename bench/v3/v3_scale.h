#pragma once
/// @file v3_scale.h
/// bench_v3 --scale: bench_compare's scaling series (many pyramids, 990 to 100100 bodies) run by
/// impulse2d and Box2D v3 alternated at equal vector width, read per body (issue 33, "Scale"):
/// each engine's CPU time per body per step at every size, its growth from the smallest size
/// (per round, then the median), the ratio ours / v3 at each size and the heap each world holds
/// per body; printed and written.

#include <ostream>
#include <string>
#include <vector>

#include "bench/v3/v3_protocol.h"

namespace impulse2d::bench_v3 {

/// The growth impulse2d's cost per body may show from the smallest size to the largest (issue
/// 33, goal 4: less than this). Printed beside the measured growth, never enforced.
constexpr double scale_goal_growth = 1.3;

/// CPU time per body per step, microseconds: 1000 `ms_per_step` / `bodies` (`bodies` >= 1).
double micros_per_body(double ms_per_step, int bodies);

/// `numerators[r] / denominators[r]` for every round r; throws `std::invalid_argument` when
/// the lengths differ or a denominator is not positive.
std::vector<double> per_round_ratios(const std::vector<double>& numerators,
                                     const std::vector<double>& denominators);

/// One size of the series at one vector width: impulse2d's runs and v3's, one of each per round.
struct ScalePoint {
  int bodies = 0;                      ///< dynamic bodies
  std::vector<RunResult> ours_runs;    ///< per round
  std::vector<RunResult> theirs_runs;  ///< per round, the same length
};

/// The cost per body per step, microseconds, of each run of `runs` (round order), at `bodies`.
std::vector<double> per_body_costs(const std::vector<RunResult>& runs, int bodies);

/// The heap per body, bytes, of each run of `runs` (round order; `RunResult::heap_bytes` /
/// `bodies`).
std::vector<double> heap_per_body(const std::vector<RunResult>& runs, int bodies);

/// The series at one vector width: impulse2d at `lanes` lanes against one v3 build.
struct ScaleWidth {
  std::string ours;                ///< impulse2d's label, e.g. "impulse2d 4 lanes"
  std::string theirs;              ///< v3's label, e.g. "Box2D v3 SSE2"
  std::vector<ScalePoint> points;  ///< fewest bodies first
  std::string skipped;             ///< not empty: why this width was not run (then no points)
};

/// Everything bench_v3 --scale prints: the heading facts and both widths.
struct ScaleReport {
  std::string commit;   ///< Box2D v3 commit, full hash
  std::string machine;  ///< CPU model and core count
  std::string load;     ///< load average before and after
  std::string command;  ///< the command line that made it
  int rounds = 0;       ///< alternated rounds
  int steps = 0;        ///< measured steps per run
  int warmup = 0;       ///< untimed steps before them
  std::vector<ScaleWidth> widths;  ///< 4 lanes vs SSE2, then 8 lanes vs AVX2
};

/// Writes `report` as plain text (`markdown` false) or as a markdown section with tables: the v3
/// commit in every heading; per width and size both engines' µs per body per step (median over
/// the rounds, [min-max]), each engine's growth from the smallest size (every round's, then
/// their median), the ratio ours / v3 (every round's, then their median), both engines' heap
/// bytes per body (median over the rounds); then per width the
/// growth from the smallest size to the largest beside the goal (< 1.3x), and the stability
/// figures at the largest size (first round). Throws `std::invalid_argument` when a width's
/// points ran different numbers of rounds or a time is not positive.
void write_scale_report(std::ostream& out, const ScaleReport& report, bool markdown);

}  // namespace impulse2d::bench_v3

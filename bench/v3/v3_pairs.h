#pragma once
/// @file v3_pairs.h
/// bench_v3's pairs: in each round impulse2d and Box2D v3 run the same scene one right after
/// the other at equal vector width, and the pair's ratio (ours / v3) is judged with its spread
/// (every pair, their median and range), not by a median alone; the table printed and written.

#include <ostream>
#include <string>
#include <vector>

#include "bench/v3/v3_protocol.h"

namespace impulse2d::bench_v3 {

/// The goal a median ratio must meet: impulse2d at most this fraction of v3's time (issue 33).
constexpr double goal_ratio = 0.9;

/// The ratios of an alternated series of pairs, summarised.
struct PairSummary {
  std::vector<double> ratios;     ///< ours / v3, one per pair, in round order
  double median = 0.0;            ///< median of `ratios` (`median`)
  double min = 0.0;               ///< smallest ratio
  double max = 0.0;               ///< largest ratio
  bool all_below_one = false;     ///< every pair had impulse2d faster
  bool median_meets_goal = false; ///< median <= `goal_ratio`
};

/// Summarises the pairs' ratios; throws `std::invalid_argument` when `ratios` is empty or one
/// is not finite and positive.
PairSummary summarize_pairs(const std::vector<double>& ratios);

/// One scene at one vector width: impulse2d's runs and v3's, one of each per round.
struct WidthSeries {
  std::string ours;                ///< impulse2d's label, e.g. "impulse2d 4 lanes"
  std::string theirs;              ///< v3's label, e.g. "Box2D v3 SSE2"
  std::vector<RunResult> ours_runs;    ///< per round
  std::vector<RunResult> theirs_runs;  ///< per round, the same length
  std::string skipped;             ///< not empty: why this width was not run (then no runs)
};

/// One scene of the report.
struct SceneSeries {
  std::string scene;                ///< scene name
  int bodies = 0;                   ///< dynamic bodies
  int steps = 0;                    ///< measured steps per run
  int warmup = 0;                   ///< untimed steps before them
  compare::Judge judge = compare::Judge::Pyramids;  ///< which stability figures apply
  std::vector<WidthSeries> widths;  ///< 4 lanes vs SSE2, then 8 lanes vs AVX2
};

/// The ratio ours / v3 of each round of `series` (`median_ms` over `median_ms`).
std::vector<double> pair_ratios(const WidthSeries& series);

/// Everything bench_v3 prints: the heading facts and the scenes.
struct Report {
  std::string commit;   ///< Box2D v3 commit, full hash
  std::string machine;  ///< CPU model and core count
  std::string load;     ///< load average before and after
  std::string command;  ///< the command line that made it
  int rounds = 0;       ///< alternated rounds
  std::vector<SceneSeries> scenes;  ///< in run order
};

/// Writes `report` as plain text (`markdown` false) or as a markdown section with tables: the
/// v3 commit in the heading; per scene and width every pair's ratio, their median and
/// [min-max], whether all pairs are below 1 and whether the median is <= 0.9, both engines'
/// median ms per step (the median over the rounds) and their stability figures.
void write_report(std::ostream& out, const Report& report, bool markdown);

}  // namespace impulse2d::bench_v3

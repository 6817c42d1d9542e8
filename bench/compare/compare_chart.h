#pragma once
/// @file compare_chart.h
/// The scaling chart of bench_compare: ms per step against body count, log-log, one line per
/// engine, drawn by gnuplot from the series' own CSV.

#include <string>
#include <vector>

#include "bench/compare/compare_report.h"

namespace impulse2d::compare {

/// Writes `directory`/scaling.csv (bodies, then one ms/step column per contender) from the
/// results marked `scaling`, and draws it into `directory`/bench_scaling.png. Returns the PNG's
/// path, or "" (with the reason in `why`) when gnuplot is not installed or there is no series.
/// Throws `std::runtime_error` when gnuplot fails.
std::string write_scaling_chart(const std::string& directory,
                                const std::vector<Contender>& contenders,
                                const std::vector<SceneResult>& results, std::string& why);

}  // namespace impulse2d::compare

#pragma once
/// @file lab_chart.h
/// The lab's speed-accuracy charts: per scenario, error (log) against cost (log), every method
/// a point, the Pareto front, the pass threshold, the recommended method and the peers.

#include <string>
#include <vector>

#include "lab/lab_result.h"

namespace impulse2d::lab {

/// Draws `<directory>/<scenario>.png` for every scenario in `results` (fronts must be marked).
/// Returns the files written. Throws `std::runtime_error` when gnuplot fails.
std::vector<std::string> draw_lab_charts(const std::vector<LabResult>& results,
                                         const std::string& directory);

}  // namespace impulse2d::lab

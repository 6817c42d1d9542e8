#pragma once
/// @file compare_scale.h
/// The scaling series read per body (issue 33, "Scale"): each engine's CPU time per body and
/// step at every size, its ratio to the smallest size, and the memory each engine's world
/// holds per body; printed, and written as `scale.csv` and `scale.md`.

#include <ostream>
#include <string>
#include <vector>

#include "bench/compare/compare_report.h"

namespace impulse2d::compare {

/// Prints, for the results marked `scaling` (in body-count order), one row per size and engine:
/// ms/step, µs per body per step, that cost divided by the same engine's at the smallest size,
/// and the heap and resident bytes per body; then per engine the ratio of its largest size's
/// per-body cost to its smallest's.
void print_scale_summary(std::ostream& out, const std::vector<Contender>& contenders,
                         const std::vector<SceneResult>& results);

/// Writes `directory`/scale.csv (scene,bodies,steps,engine,ms_per_step,us_per_body,
/// cost_vs_smallest,heap_bytes_per_body,resident_bytes_per_body) and `directory`/scale.md (the
/// same as a Markdown table, headed by `machine`). Nothing when no scaling result is present.
/// Throws `std::runtime_error` when a file cannot be written.
void write_scale_files(const std::string& directory, const std::vector<Contender>& contenders,
                       const std::vector<SceneResult>& results, const std::string& machine);

}  // namespace impulse2d::compare

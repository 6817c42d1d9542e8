#pragma once
/// @file frame_plan.h
/// Which steps of a run become frames, checked against the run's length.

#include <cstdint>
#include <string>
#include <vector>

#include "scene/frame_selection.h"

namespace impulse2d::demos {

/// The frames of one run: frame n is the world after n steps.
struct FramePlan {
  std::int64_t steps = 0;            ///< steps to simulate (the last frame's step)
  std::vector<std::int64_t> frames;  ///< selected steps, ascending, at least one
};

/// Parses `spec` (`A:B:k` ranges, see `FrameSelection`) and keeps the steps in
/// 0..`run_steps`; the run is then cut short after the last selected step. Throws
/// `UsageError` for a malformed spec, a range that ends after the run (naming both), a
/// selection with no step inside the run, or more than `limits::max_frames` frames. Costs
/// time proportional to the frames selected, not to the run's length.
FramePlan plan_frames(const std::string& spec, std::int64_t run_steps);

/// The steps of `plan` for a plan printed by --dry-run: "steps 0..100" (every step), "steps
/// 0, 10, .. 300 (every 10th)" (a stride), else the first and last steps listed.
std::string describe_frame_steps(const FramePlan& plan);

/// `count` steps spread evenly over 0..`run_steps` (both ends included when count >= 2).
FramePlan spread_frames(int count, std::int64_t run_steps);

}  // namespace impulse2d::demos

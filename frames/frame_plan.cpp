/// @file frame_plan.cpp
#include "frames/frame_plan.h"

#include "scene/run_limits.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

FramePlan plan_frames(const std::string& spec, std::int64_t run_steps) {
  FrameSelection selection;
  try {
    selection = FrameSelection::parse(spec);
  } catch (const UsageError& error) {
    throw UsageError(std::string("--frames: ") + error.what());
  }
  const std::string run =
      "the run (steps 0.." + std::to_string(run_steps) + "; change it with --steps)";
  if (selection.last() && *selection.last() > run_steps) {
    throw UsageError("--frames '" + spec + "' ends at step " + std::to_string(*selection.last()) +
                     ", after the end of " + run);
  }
  FramePlan plan;
  plan.frames = selection.steps_up_to(run_steps, static_cast<std::size_t>(limits::max_frames));
  if (plan.frames.empty()) throw UsageError("--frames '" + spec + "' selects no step of " + run);
  if (plan.frames.size() > static_cast<std::size_t>(limits::max_frames)) {
    throw UsageError("--frames '" + spec + "' selects more than " +
                     std::to_string(limits::max_frames) +
                     " frames (the limit of one run); select fewer, e.g. with a stride A:B:k");
  }
  plan.steps = plan.frames.back();
  return plan;
}

FramePlan spread_frames(int count, std::int64_t run_steps) {
  FramePlan plan;
  for (int i = 0; i < count; ++i) {
    // run_steps * i / (count - 1) without forming the product (no overflow for any run).
    const std::int64_t parts = count - 1;
    const std::int64_t step = count == 1 ? run_steps
                                         : run_steps / parts * i + run_steps % parts * i / parts;
    if (plan.frames.empty() || plan.frames.back() != step) plan.frames.push_back(step);
  }
  plan.steps = plan.frames.back();
  return plan;
}

}  // namespace impulse2d::demos

namespace impulse2d::demos {

std::string describe_frame_steps(const FramePlan& plan) {
  const std::vector<std::int64_t>& steps = plan.frames;
  const std::size_t count = steps.size();
  if (count == 1) return "step " + std::to_string(steps.front());
  const std::int64_t stride = steps[1] - steps[0];
  bool even = true;
  for (std::size_t i = 2; i < count && even; ++i) even = steps[i] - steps[i - 1] == stride;
  const std::string ends = std::to_string(steps.front()) + ", " + std::to_string(steps[1]) +
                           ", .. " + std::to_string(steps.back());
  if (even && stride == 1) return "steps " + std::to_string(steps.front()) + ".." + std::to_string(steps.back());
  if (even) return "steps " + ends + " (every " + std::to_string(stride) + ")";
  std::string text = "steps";
  const std::size_t shown = count <= 8 ? count : 6;
  for (std::size_t i = 0; i < shown; ++i) text += (i == 0 ? " " : ", ") + std::to_string(steps[i]);
  if (shown < count) text += ", .. " + std::to_string(steps.back());
  return text;
}

}  // namespace impulse2d::demos

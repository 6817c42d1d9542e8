#pragma once
/// @file timeline_frames.h
/// The `--timeline` strip under each frame of a sequence: the run is simulated once ahead to
/// record energy, contacts and the deepest penetration at every step, and each frame gets the
/// strip with its own step marked.

#include "render/frame.h"
#include "render/frame_renderer.h"
#include "render/timeline_strip.h"

#include <cstdint>
#include <vector>

namespace impulse2d::demos {

class SceneRun;

/// The samples of a run of `run`'s scene and parameters (a separate run, from the start) up to
/// `steps`: one every `steps / 2048` steps (at least every step), the last step included.
std::vector<render::TimelineSample> record_timeline(const SceneRun& run, std::int64_t steps);

/// Draws the strip under frames of one width.
class TimelineFrames {
 public:
  /// Records `run`'s timeline up to `steps` (`record_timeline`) and creates a renderer for the
  /// strip under width x height frames in `theme`.
  TimelineFrames(const SceneRun& run, std::int64_t steps, int width, int height, render::Theme theme);
  /// Rows the strip adds under each frame, pixels.
  int strip_height() const { return strip_.height(); }
  /// Appends the strip, with `step` marked, under `frame` (which must be as wide as the strip).
  void append(render::Frame& frame, std::int64_t step);

 private:
  std::vector<render::TimelineSample> samples_;
  render::Theme theme_;
  int scale_ = 1;
  render::FrameRenderer strip_;
  render::Frame strip_frame_;
};

}  // namespace impulse2d::demos

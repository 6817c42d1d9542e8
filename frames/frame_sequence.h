#pragma once
/// @file frame_sequence.h
/// Renders a scene run into a PNG frame sequence (`dir/<scene>_<frame:05>.png`, frames
/// numbered 0, 1, 2, ... whatever steps they show, with the step in each PNG's metadata and
/// in `dir/<scene>_frames.csv`), optionally also a video, with all-or-nothing output.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/debug_draw.h"
#include "frames/frame_plan.h"
#include "scene/scene_run.h"
#include "frames/trail_selection.h"
#include "render/palette.h"

namespace impulse2d::demos {

/// How frames look and where they go.
struct FrameSequenceOptions {
  int width = 800;                             ///< pixels
  int height = 600;                            ///< pixels
  DebugDrawOptions draw;                       ///< overlay flags and arrow scales
  render::Theme theme = render::Theme::Light;  ///< colours
  std::filesystem::path directory = "out";     ///< created if missing
  bool write_frames = true;                    ///< false: the video only (needs `video`)
  std::optional<std::filesystem::path> video;  ///< also encode an .mp4 / .webm / .gif here
  std::optional<double> frames_per_second;     ///< video rate; real time when absent
  int writer_threads = 2;                      ///< PNG encoding threads
  TrailSelection trails;                       ///< bodies whose recent path is drawn
  bool clean = false;  ///< replace frames of the same scene already in `directory`
  std::string parameters;  ///< parameter overrides "rows=8 seed=3", for the PNG metadata
  bool html = false;  ///< also the browser viewer `<scene>.html` and its overlay variants
                      ///< `<scene>.overlays/` (only with `write_frames`)
};

/// What was written.
struct FrameSequenceResult {
  std::filesystem::path first_file;  ///< the first frame (empty without `write_frames`)
  std::filesystem::path last_file;   ///< the last frame (empty without `write_frames`)
  std::filesystem::path index_file;  ///< `<scene>_frames.csv` (empty without `write_frames`)
  std::filesystem::path html_file;   ///< `<scene>.html` (empty without `html`)
  std::int64_t frame_count = 0;      ///< frames written
  double seconds = 0.0;              ///< wall-clock time of the whole job
};

/// Called after each frame with the number of frames finished.
using FrameProgress = std::function<void(std::int64_t frames_done)>;

/// The checks `render_frame_sequence` makes of its outputs before any work, for a dry run to
/// make them too: the video's folder and the frames' folder can be written or created
/// (`std::runtime_error` naming --video / --out), and the folder holds no frames (viewer,
/// overlay variants) of `scene_name` unless `options.clean` (`UsageError`). Returns those
/// earlier files, which a clean run replaces.
std::vector<std::filesystem::path> check_sequence_output(const std::string& scene_name,
                                                         const FrameSequenceOptions& options);

/// Steps `run` to `plan.steps`, rendering each planned step into a staging directory inside
/// `options.directory`, and moves the frames and their index into place only when every
/// frame (and the video) succeeded; with `options.html` the browser viewer `<scene>.html`
/// (see html_viewer.h) goes with them. Without `options.write_frames` only the video is written
/// and the directory is left alone. Throws `UsageError` before any work when the directory already holds
/// frames of the scene and `options.clean` is off (with it, they are removed just before the
/// new frames move in). On any failure (unwritable directory, renderer, a scene event, a
/// signal: `Interrupted` saying what was removed) every file and directory this call created
/// is removed; files that existed before are never touched.
FrameSequenceResult render_frame_sequence(SceneRun& run, const FramePlan& plan,
                                          const FrameSequenceOptions& options,
                                          const FrameProgress& progress);

/// "tutorial - left: no friction | right: friction": the scene's name and caption for HUDs.
std::string scene_title(const Scene& scene);

}  // namespace impulse2d::demos

#pragma once
/// @file commands.h
/// The commands of the `impulse2d` program as plain functions of their arguments (the
/// command-line parsing lives in cli.cpp). Each writes its report to `out` and progress to
/// stderr, and throws `UsageError` for bad input and other exceptions for runtime failures.

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "app/view_options.h"

namespace impulse2d::demos {

/// Arguments shared by every command that runs a scene.
struct SceneArguments {
  std::string scene;                  ///< built-in name or path to a .json file
  std::vector<std::string> params;    ///< "key=value" overrides
  std::optional<std::int64_t> steps;  ///< run length override
  bool strict = false;                ///< a diverged body is an error, not a warning
};

/// `impulse2d render`.
struct RenderArguments {
  SceneArguments scene;                 ///< what to run
  std::optional<std::string> frames;    ///< `A:B:k` ranges; the scene's default when absent
  std::string size = "800x600";         ///< WxH pixels
  std::optional<std::string> overlays;  ///< overlay list; the scene's default when absent
  std::string theme = "light";          ///< light or dark
  std::string out = "out";              ///< directory
  std::optional<std::string> video;     ///< .mp4 / .webm / .gif path
  std::optional<double> fps;            ///< video frames per second; real time when absent
  bool no_frames = false;               ///< write the video only, no PNG frames
  int threads = 2;                      ///< PNG encoding threads
  std::optional<std::string> trails;    ///< `dynamic` or body indices with motion trails
  bool clean = false;                   ///< replace frames of the same scene already in `out`
  bool quiet = false;                   ///< no progress and no summary line
  ViewArguments view;                   ///< HUD, legend, scales, camera, highlight
  bool html = false;                    ///< also write the browser viewer `<scene>.html`
};

/// `impulse2d trace`.
struct TraceArguments {
  SceneArguments scene;        ///< what to run (the scene's length unless steps is given)
  std::int64_t every = 1;      ///< sample every k-th step
  std::string format = "csv";  ///< csv or json
};

/// `impulse2d sheet`.
struct SheetArguments {
  SceneArguments scene;                 ///< what to run
  std::optional<std::string> frames;    ///< `A:B:k` ranges; `count` evenly spread when absent
  int count = 8;                        ///< frames when `frames` is absent
  int columns = 4;                      ///< tiles per row
  std::string tile = "400x300";         ///< WxH pixels per tile
  std::optional<std::string> overlays;  ///< overlay list; the scene's default when absent
  std::string theme = "light";          ///< light or dark
  std::optional<std::string> out;       ///< PNG path; out/contact_sheet_<scene>.png when absent
  std::optional<std::string> trails;    ///< `dynamic` or body indices with motion trails
  bool quiet = false;                   ///< no summary line
  ViewArguments view;                   ///< legend, scales, camera, highlight
};

/// Prints every built-in scene with its description, parameters and model.
void list_scenes(std::ostream& out);
/// Renders a frame sequence (and optionally a video); prints where the frames went unless
/// `arguments.quiet`.
void render_scene(const RenderArguments& arguments, std::ostream& out);
/// Writes the trace of a run to `out`.
void trace_scene(const TraceArguments& arguments, std::ostream& out);
/// Writes a contact sheet; prints where it went unless `arguments.quiet`.
void sheet_scene(const SheetArguments& arguments, std::ostream& out);

/// Checks what a scene command would run without running it: the scene (name or file, the
/// default scene when empty), its parameters and length, and `frames` when given. Throws
/// `UsageError` as the command would, before any work.
void check_scene_arguments(const SceneArguments& arguments, const std::optional<std::string>& frames);

/// Parses "WxH" (each 16..8192). Throws `UsageError` naming `option`.
std::pair<int, int> parse_size(const std::string& text, const std::string& option);

}  // namespace impulse2d::demos

#pragma once
/// @file scene_command.h
/// What the commands that run a scene (render, trace, sheet and the default demo) share: the
/// scene, its parameters and length from the command line, their options, and the checks and
/// warnings around a run.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "frames/trail_selection.h"
#include "render/palette.h"
#include "scene/scene.h"
#include "scene/scene_run.h"

namespace CLI {
class App;
}

namespace impulse2d::demos {

/// Arguments shared by every command that runs a scene.
struct SceneArguments {
  std::string scene;                  ///< built-in name or path to a .json file
  std::vector<std::string> params;    ///< "key=value" overrides
  std::optional<std::int64_t> steps;  ///< run length override
  bool strict = false;                ///< a diverged body is an error, not a warning
  /// Threads sharing each step (`WorldSettings::worker_count`, `--workers`): 1..64. The states
  /// are bit-identical for any count; only the speed changes.
  int workers = 1;
};

/// A scene resolved from the arguments together with its parameters.
struct ResolvedScene {
  Scene scene;              ///< the built-in scene or the file's
  Params params;            ///< its parameters with the overrides applied
  std::int64_t steps = 0;   ///< length of the run
};

/// Adds the scene argument (`required` or not), `--param`, `--strict` and `--workers` to
/// `command`.
void add_scene_options(CLI::App& command, SceneArguments& arguments, bool scene_required);
/// Adds `--backend osmesa|egl` to a command that renders.
void add_backend_option(CLI::App& command, std::string& backend);
/// The help text of `--overlays`: every overlay with its description.
std::string overlay_help();

/// Resolves the scene, applies the parameters and the worker count, checks the length, and (with
/// `check_events`) the events against it (`check_events_in_run` up to `steps`). Throws
/// `UsageError`.
ResolvedScene resolve(const SceneArguments& arguments, bool check_events = true);
/// Throws `UsageError` naming the first event of the scene after `last_step`, the last step of
/// the run: it would never happen.
void check_events_in_run(const ResolvedScene& resolved, std::int64_t last_step);
/// A run of the resolved scene, strict when asked.
std::unique_ptr<SceneRun> start_run(const ResolvedScene& resolved, const SceneArguments& arguments);

/// Throws `UsageError` for a trail body index no body of the run can have.
void check_trails(const TrailSelection& trails, const SceneRun& run, const std::string& option);
/// Prints a warning per diverged body (the first 10, then a count) to stderr.
void warn_divergences(const SceneRun& run);
/// The theme named `name` (light or dark). Throws `UsageError` naming --theme.
render::Theme theme_of(const std::string& name);
/// Parses "WxH" (each side 16..8192, digits only). Throws `UsageError` naming `option`.
std::pair<int, int> parse_size(const std::string& text, const std::string& option);
/// The draw flags of an `--overlays` list. Throws `UsageError` naming --overlays.
std::uint32_t parse_overlays_option(const std::string& list);

}  // namespace impulse2d::demos

#pragma once
/// @file view_options.h
/// The command line's view options shared by `render` and `sheet`: HUD and legend switches,
/// overlay scales, text size, camera (`--view`, `--follow`, `--zoom`), `--highlight`, island
/// colours, feature ids, and the HUD's solver settings and step timings.

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace impulse2d::demos {

struct Scene;
class SceneRun;

/// What the view options asked for; unset options keep the scene's own view.
struct ViewArguments {
  std::optional<bool> hud;                ///< --hud / --no-hud
  std::optional<bool> legend;             ///< --legend / --no-legend
  std::optional<float> arrow_scale;       ///< --arrow-scale: factor on impulse and velocity arrows
  std::optional<float> penetration_scale; ///< --penetration-scale: overlap magnification
  std::optional<int> text_scale;          ///< --text-scale: font magnification (1 = 7 px capitals)
  std::optional<float> max_arrow_pixels;  ///< --max-arrow: contact arrows cut at this length, pixels
  std::optional<std::string> view;        ///< --view x0,y0:x1,y1 (metres)
  std::optional<std::string> follow;      ///< --follow BODY (name or creation index)
  std::optional<float> zoom;              ///< --zoom K
  std::optional<std::string> highlight;   ///< --highlight BODY (name or creation index)
  bool islands = false;                   ///< --islands: island colours
  bool feature_ids = false;               ///< --feature-ids: contact feature ids
  bool timeline = false;                  ///< --timeline: the run's timeline under each frame
  bool settings = false;                  ///< --hud-settings: solver settings in the HUD
  bool timings = false;                   ///< --hud-timings: per-stage step times in the HUD
};

/// Adds the view options to `command`, storing into `arguments` (which must outlive parsing);
/// the HUD options and `--timeline` only when `sequence` (a contact sheet has neither: its
/// tiles are labelled by the sheet).
void add_view_options(CLI::App& command, ViewArguments& arguments, bool sequence);

/// Applies `arguments` to `scene.view` (camera, switches, scales). Throws `UsageError` naming
/// the option for a value out of range, a malformed `--view`, an unknown body name, or
/// `--view` together with `--follow`.
void apply_view_arguments(const ViewArguments& arguments, Scene& scene);

/// Throws `UsageError` when the view's followed or highlighted body index is one no body of
/// `run` can have (naming `--follow` / `--highlight`).
void check_view_bodies(const ViewArguments& arguments, const SceneRun& run);

/// Throws `UsageError` when the camera of `run`'s scene view (after `apply_view_arguments`)
/// on a `width` x `height` image has a scale outside limits::min_pixels_per_metre ..
/// limits::max_pixels_per_metre, naming the options (--view, --follow, --zoom) or the scene
/// file's camera that chose it.
void check_camera(const ViewArguments& arguments, const SceneRun& run, int width, int height);

}  // namespace impulse2d::demos

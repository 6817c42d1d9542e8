#pragma once
/// @file scene.h
/// A scene: how to build a world, what physics it needs, how to look at it, and what happens
/// while it runs. Built-in scenes are C++ (demos/scenes/*.cpp); scene files are JSON.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/debug_draw.h"
#include "core/settings.h"
#include "core/shape.h"
#include "scene/params.h"
#include "scene/scene_event.h"
#include "scene/scene_model.h"
#include "scene/step_script.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// Where the camera looks. It stays fixed for the whole run unless it follows a body.
struct CameraSpec {
  /// How the view is chosen.
  enum class Mode {
    FitWorld,   ///< fit the bounds of every body as built (before the first step)
    FitBounds,  ///< fit `bounds`
    Centered,   ///< `center` at the image centre, `pixels_per_metre` zoom
    /// Each frame centred on a body, `pixels_per_metre` zoom: the scene script's
    /// `followed_body()` when it names one, else the body of creation index `follow_body`;
    /// `center` until that body exists.
    Follow,
  };
  Mode mode = Mode::FitWorld;      ///< which of the fields below apply
  Aabb bounds;                     ///< FitBounds: world rectangle shown whole, metres
  vec2 center{0.0f, 0.0f};         ///< Centered (and Follow's start): image centre, metres
  /// Centered, Follow: zoom, pixels per metre. For Follow, 0 means the zoom (and start) that
  /// fits the world as built (the command line's `--follow` on a scene without a camera).
  float pixels_per_metre = 40.0f;
  float zoom = 1.0f;  ///< multiplies the zoom of any mode, about the view's centre (> 0)
  /// Follow: creation index (the scene's bodies in order); -1 for the script's body only.
  int follow_body = 0;
};

/// Overlay scales of a scene view before any scene or option changes them: as
/// `DebugDrawOptions`, with penetration magnified 10x so resting overlaps of ~1 cm read.
DebugDrawOptions default_view_draw();

/// The defaults of a rendered run; the command line overrides each.
struct SceneView {
  CameraSpec camera;           ///< where the camera looks
  std::int64_t steps = 600;    ///< length of a run, steps
  std::string frames = "::2";  ///< which steps become frames (`FrameSelection` syntax)
  /// Overlays on by default (`flags`) and their arrow scales; the theme sets the palette.
  DebugDrawOptions draw = default_view_draw();
  bool show_hud = true;     ///< the HUD text block (scene, frame, time, counts)
  bool show_legend = true;  ///< the overlay legend
  int text_scale = 0;       ///< HUD, legend and label text magnification; 0 = by frame size
  float max_arrow_pixels = 120.0f;  ///< contact arrows are cut at this length, pixels at scale 1
  int highlight_body = -1;  ///< creation index of the body framed in every frame; -1 for none
  bool show_settings = false;  ///< the solver settings as HUD lines
  bool show_islands = false;      ///< island colours: bodies joined by contacts share a colour
  bool show_feature_ids = false;  ///< each contact point's feature id
  /// A strip under each frame of a sequence: energy, contacts and deepest penetration over the
  /// whole run, the frame's step marked (the run is simulated once ahead to draw it).
  bool show_timeline = false;
  /// Per-stage step timings as a HUD line. Wall-clock: frames differ run to run, so never in
  /// goldens.
  bool show_timings = false;
  std::string caption;  ///< shown in the HUD after the scene name (may be empty)
};

/// Makes the per-step script of one run from the run's parameters.
using ScriptFactory = std::function<std::unique_ptr<StepScript>(const Params&)>;

/// Everything about one scene.
struct Scene {
  std::string name;               ///< registry key and file-name prefix, e.g. "pyramid"
  std::string description;        ///< one line for `impulse2d list`
  std::vector<ParamSpec> params;  ///< named parameters with defaults and ranges
  SceneModel model;               ///< the physics it needs (applied to `settings` when run)
  WorldSettings settings;         ///< method choices: gravity, time step, solver, mixing rules, ...
  SceneView view;                 ///< camera, run length, frames, overlays
  /// Creates the scene's bodies in a world that already has `settings` and the model applied.
  std::function<void(World&, const Params&)> build;
  ScriptFactory script;             ///< optional per-step behaviour (empty: none)
  std::vector<SceneEvent> events;   ///< scripted events, any order (sorted by the run)
  /// Joints the run creates right after `build`, in this order (scene files' `joints`;
  /// built-in scenes usually create theirs in `build`). Named ones can be named by events.
  std::vector<JointSpec> joints;
  /// Things a scene file allows but that are probably mistakes ("<file>: <path>: <reason>"),
  /// printed as warnings when the file is loaded.
  std::vector<std::string> warnings;
  std::string source = "built-in";  ///< "built-in" or the scene file's path
  std::map<int, std::string> body_names;  ///< creation index -> name given in the scene file
};

}  // namespace impulse2d::demos

/// @file view_options.cpp
#include "app/view_options.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/strict_number_check.h"
#include "frames/scene_camera.h"
#include "scene/json_cursor.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"
#include "scene/scene_run.h"
#include "scene/strict_number.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

namespace {

/// `value` checked against [minimum, maximum]; the message names `option` and `meaning`.
float checked(float value, float minimum, float maximum, const std::string& option, const std::string& meaning) {
  if (!(value >= minimum && value <= maximum)) {
    char range[96];
    std::snprintf(range, sizeof(range), "%g: must be in %g..%g (", static_cast<double>(value),
                  static_cast<double>(minimum), static_cast<double>(maximum));
    throw UsageError(option + " " + range + meaning + ")");
  }
  return value;
}

/// A body named in the scene file, or a creation index (digits only).
int body_reference(const std::string& text, const Scene& scene, const std::string& option) {
  if (text.empty()) {
    throw UsageError(option + " '': an empty body name (give a name from the scene file or a "
                     "creation index 0, 1, ...)");
  }
  for (const auto& [index, name] : scene.body_names) {
    if (name == text) return index;
  }
  const std::optional<std::int64_t> index = parse_whole_number(text, 1000000);
  if (!index) {
    std::string known;
    for (const auto& [unused, name] : scene.body_names) known += (known.empty() ? "" : ", ") + name;
    throw UsageError(option + " '" + text + "': no body of scene " + scene.name + " has that name; give a name" +
                     (known.empty() ? std::string(" (this scene names none)") : " (" + known + ")") +
                     " or a creation index 0, 1, ... (as the ids overlay shows them)");
  }
  return static_cast<int>(*index);
}

/// Parses "x0,y0:x1,y1" (metres, each |v| <= limits::max_coordinate) into bounds whose sides
/// are at least limits::min_view_side.
Aabb view_bounds(const std::string& text) {
  const std::string syntax =
      "expected x0,y0:x1,y1 in metres, the lower-left then the upper-right corner (x1 > x0, "
      "y1 > y0, each coordinate within +-" + compact_number(limits::max_coordinate) +
      "), e.g. --view -5,0:5,8";
  float values[4];
  std::size_t start = 0;
  for (int i = 0; i < 4; ++i) {
    const char separator = i == 1 ? ':' : i == 3 ? '\0' : ',';
    const std::size_t end = separator == '\0' ? text.size() : text.find(separator, start);
    const std::optional<double> value =
        end == std::string::npos ? std::nullopt : parse_decimal(text.substr(start, end - start), true);
    if (!value || std::fabs(*value) > limits::max_coordinate) {
      throw UsageError("--view '" + text + "': " + syntax);
    }
    values[i] = static_cast<float>(*value);
    start = end + 1;
  }
  if (!(values[2] > values[0] && values[3] > values[1])) throw UsageError("--view '" + text + "': " + syntax);
  const float width = values[2] - values[0];
  const float height = values[3] - values[1];
  if (!(width >= limits::min_view_side && height >= limits::min_view_side)) {
    throw UsageError("--view '" + text + "': the rectangle is " + compact_number(width) + " x " +
                     compact_number(height) + " m; each side must be at least " +
                     compact_number(limits::min_view_side) + " m (the smallest body)");
  }
  return Aabb{vec2(values[0], values[1]), vec2(values[2], values[3])};
}

}  // namespace

void add_view_options(CLI::App& command, ViewArguments& arguments, bool sequence) {
  if (sequence) {
    CLI::Option* hud = command.add_flag_callback("--hud", [&arguments] { arguments.hud = true; },
                                                 "draw the HUD (scene, frame, time, counts; default on)");
    CLI::Option* no_hud = command.add_flag_callback("--no-hud", [&arguments] { arguments.hud = false; },
                                                    "leave the HUD out");
    hud->excludes(no_hud);
    command.add_flag("--hud-settings", arguments.settings, "add the solver settings to the HUD");
    command.add_flag("--hud-timings", arguments.timings,
                     "add the last step's per-stage times to the HUD (wall-clock: frames differ run to run)");
    command.add_flag("--timeline", arguments.timeline,
                     "a strip under each frame: energy, contacts and deepest penetration over the "
                     "whole run, the frame's step marked");
  }
  CLI::Option* legend = command.add_flag_callback("--legend", [&arguments] { arguments.legend = true; },
                                                  "draw the overlay legend (default on)");
  CLI::Option* no_legend = command.add_flag_callback(
      "--no-legend", [&arguments] { arguments.legend = false; }, "leave the legend out");
  legend->excludes(no_legend);
  command.add_option("--arrow-scale", arguments.arrow_scale,
                     "factor on the scene's impulse and velocity arrow lengths (0.001..1000)")
      ->check(decimal_check());
  command.add_option("--penetration-scale", arguments.penetration_scale,
                     "magnification of penetration bars (1..1000; default 10)")
      ->check(decimal_check());
  command.add_option("--text-scale", arguments.text_scale,
                     "HUD, legend and label text size, 1 = 7 px capitals (1..16; default by frame size)")
      ->check(whole_number_check());
  command.add_option("--max-arrow", arguments.max_arrow_pixels,
                     "contact arrows longer than this many pixels are cut and marked // (8..4096; default 120)")
      ->check(decimal_check());
  command.add_option("--view", arguments.view, "camera on this world rectangle: x0,y0:x1,y1 (metres)");
  command.add_option("--follow", arguments.follow,
                     "camera centred on this body in every frame: a name from the scene file or a creation index");
  command.add_option("--zoom", arguments.zoom, "magnify the camera about its centre by K (0.01..100)")
      ->check(decimal_check());
  command.add_option("--highlight", arguments.highlight, "frame this body (name or creation index) in magenta");
  command.add_flag("--islands", arguments.islands,
                   "island colours: a dot per body and a line per contact, one colour per island");
  command.add_flag("--feature-ids", arguments.feature_ids, "write each contact point's feature id (hex)");
}

void apply_view_arguments(const ViewArguments& arguments, Scene& scene) {
  SceneView& view = scene.view;
  if (arguments.hud) view.show_hud = *arguments.hud;
  if (arguments.legend) view.show_legend = *arguments.legend;
  if (arguments.arrow_scale) {
    const float scale = checked(*arguments.arrow_scale, 0.001f, 1000.0f, "--arrow-scale",
                                "a factor on the scene's impulse and velocity arrows");
    view.draw.impulse_scale *= scale;
    view.draw.velocity_scale *= scale;
  }
  if (arguments.penetration_scale) {
    view.draw.penetration_scale =
        checked(*arguments.penetration_scale, 1.0f, 1000.0f, "--penetration-scale", "a magnification of overlaps");
  }
  if (arguments.text_scale) {
    view.text_scale = static_cast<int>(checked(static_cast<float>(*arguments.text_scale), 1.0f, 16.0f,
                                               "--text-scale", "a whole font magnification"));
  }
  if (arguments.max_arrow_pixels) {
    view.max_arrow_pixels = checked(*arguments.max_arrow_pixels, 8.0f, 4096.0f, "--max-arrow", "pixels");
  }
  if (arguments.view && arguments.follow) {
    throw UsageError("--view and --follow both choose the camera; give one (--zoom works with either)");
  }
  if (arguments.view) {
    view.camera.mode = CameraSpec::Mode::FitBounds;
    view.camera.bounds = view_bounds(*arguments.view);
  }
  if (arguments.follow) {
    const bool has_zoom = view.camera.mode == CameraSpec::Mode::Centered || view.camera.mode == CameraSpec::Mode::Follow;
    if (!has_zoom) view.camera.pixels_per_metre = 0.0f;  // the zoom that fits the world as built
    view.camera.mode = CameraSpec::Mode::Follow;
    view.camera.follow_body = body_reference(*arguments.follow, scene, "--follow");
  }
  if (arguments.zoom) {
    view.camera.zoom = checked(*arguments.zoom, 0.01f, 100.0f, "--zoom", "a magnification of the camera");
  }
  if (arguments.highlight) view.highlight_body = body_reference(*arguments.highlight, scene, "--highlight");
  if (arguments.islands) view.show_islands = true;
  if (arguments.feature_ids) view.show_feature_ids = true;
  if (arguments.timeline) view.show_timeline = true;
  if (arguments.settings) view.show_settings = true;
  if (arguments.timings) view.show_timings = true;
}

void check_view_bodies(const ViewArguments& arguments, const SceneRun& run) {
  const auto check = [&](const std::optional<std::string>& given, int index, const char* option) {
    if (!given || index < run.bodies_in_run()) return;
    throw UsageError(std::string(option) + " " + *given + ": body " + std::to_string(index) +
                     " does not exist (scene " + run.scene().name + " has " + std::to_string(run.bodies_in_run()) +
                     " bodies, 0.." + std::to_string(run.bodies_in_run() - 1) + ")");
  };
  check(arguments.follow, run.scene().view.camera.follow_body, "--follow");
  check(arguments.highlight, run.scene().view.highlight_body, "--highlight");
}

}  // namespace impulse2d::demos

namespace impulse2d::demos {

void check_camera(const ViewArguments& arguments, const SceneRun& run, int width, int height) {
  const CameraSpec& spec = run.scene().view.camera;
  const float scale = scene_camera(spec, run.world(), width, height).pixels_per_metre();
  if (scale >= limits::min_pixels_per_metre && scale <= limits::max_pixels_per_metre) return;
  std::string cause;
  if (arguments.view) cause += "--view " + *arguments.view + " ";
  if (arguments.follow) cause += "--follow " + *arguments.follow + " ";
  if (arguments.zoom) cause += "--zoom " + compact_number(*arguments.zoom) + " ";
  if (cause.empty()) {
    cause = run.scene().source == "built-in" ? "the camera of scene " + run.scene().name + " "
                                             : run.scene().source + ": camera ";
  }
  throw UsageError(cause + "on " + std::to_string(width) + "x" + std::to_string(height) +
                   " pixels gives " + compact_number(scale) + " pixels per metre; accepted " +
                   compact_number(limits::min_pixels_per_metre) + ".." +
                   compact_number(limits::max_pixels_per_metre) + " (" +
                   limits::pixels_per_metre_reason + "; change --zoom or --view)");
}

}  // namespace impulse2d::demos

#pragma once
/// @file hud.h
/// The heads-up display: a text block (scene, frame, simulated time, counts) and a legend
/// with one colour key per overlay that is on, drawn in screen space with stb_easy_font.

#include "core/debug_draw.h"
#include "render/camera.h"
#include "render/palette.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impulse2d::render {

class PrimitiveRenderer;

/// What the HUD says that the world does not know.
struct HudInfo {
  std::string scene_name;  ///< shown first
  std::int64_t frame = 0;  ///< frame number of the sequence
  /// Wall-clock milliseconds of the last step. Shown only when set: it differs from run to
  /// run, so it makes frames non-reproducible.
  std::optional<double> step_milliseconds;
  /// Wall-clock frames per second. Shown only when set, for the same reason.
  std::optional<double> frames_per_second;
  /// Further lines asked for (solver settings, per-stage step timings), shown after the others.
  std::vector<std::string> extra_lines;
};

/// The simulation figures the HUD reports, read from a world.
struct HudCounts {
  double simulated_time = 0.0;  ///< seconds
  int body_count = 0;           ///< living bodies
  int contact_count = 0;        ///< touching pairs
  int contact_point_count = 0;  ///< manifold points over all touching pairs
  /// Pairs of sleeping bodies whose contacts the world keeps aside (shown only when > 0).
  int sleeping_contact_count = 0;
};

/// One row of the legend: a colour key and what it means.
struct LegendEntry {
  Color color;        ///< the overlay's colour
  std::string label;  ///< its meaning, with its scale when it has one
};

/// The HUD's lines of text, top to bottom.
std::vector<std::string> hud_lines(const HudInfo& info, const HudCounts& counts);

/// One entry per overlay flag that is on in `options` (shapes have none), plus motion trails
/// when `trails_on`, in flag order. Arrow scales are given as what 50 pixels stand for under
/// `camera`. With any contact arrow on, one more row says that contact arrows longer than
/// `max_arrow_pixels` are cut there with a break mark; penetration says its magnification and
/// the shortest bar drawn, `min_penetration_pixels` (both pixels, as drawn).
std::vector<LegendEntry> legend_entries(const DebugDrawOptions& options, const Camera& camera,
                                        bool trails_on, Color trail_color, float max_arrow_pixels,
                                        float min_penetration_pixels);

/// Draws the HUD text (top-left, lines wrapped at spaces to the frame's width) and, when `legend` is not empty, the legend (where
/// `layout_hud` puts it, never over the HUD), each on a translucent panel, at integer
/// `text_scale`.
void draw_hud(PrimitiveRenderer& renderer, const std::vector<std::string>& lines,
              const std::vector<LegendEntry>& legend, const ThemePalette& palette, int text_scale);

}  // namespace impulse2d::render

#pragma once
/// @file hud.h
/// The heads-up display: one line of fields (scene, step, frame, simulated time, counts) and a
/// compact legend with one colour key per overlay drawn in the frame, drawn in screen space
/// with stb_easy_font where `layout_hud` puts them.

#include "core/debug_draw.h"
#include "render/camera.h"
#include "render/palette.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;
struct HudLayout;

/// What the HUD says that the world does not know.
struct HudInfo {
  /// The scene's title, shown first: "name - description"; the description is left out when
  /// the HUD line has no room for it.
  std::string scene_name;
  std::int64_t step = 0;  ///< the world's step count the frame shows ("step N")
  /// The frame's number in its sequence, shown ("frame i") when set and different from `step`.
  std::optional<std::int64_t> frame_index;
  /// Wall-clock milliseconds of the last step. Shown only when set: it differs from run to
  /// run, so it makes frames non-reproducible.
  std::optional<double> step_milliseconds;
  /// Wall-clock frames per second. Shown only when set, for the same reason.
  std::optional<double> frames_per_second;
  /// Further lines asked for (solver settings, per-stage step timings), shown under the HUD line.
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

/// The HUD's text: one line of fields, most important first, and the lines asked for.
struct HudText {
  /// Scene title, "step N", "frame i" (when it differs), "t = T s", body and contact counts,
  /// wall-clock figures (when set). The layout keeps as many as fit on one line.
  std::vector<std::string> fields;
  /// `HudInfo::extra_lines`, each drawn whole under the line of fields.
  std::vector<std::string> extra_lines;
};

/// One item of the legend: a colour key and a short name, or (without `swatch`) a note such
/// as an arrow scale.
struct LegendEntry {
  Color color;         ///< the overlay's colour
  std::string label;   ///< a short name ("normal", "impulse") or the note's text
  bool swatch = true;  ///< false for a note: text only
};

/// The HUD's text for `info` and `counts`.
HudText hud_text(const HudInfo& info, const HudCounts& counts);

/// The figures of `world` the HUD reports.
HudCounts hud_counts(const World& world);

/// The overlay flags of `flags` that leave a mark on `world` as it is: contact marks only where
/// there are contact points (impulses where an impulse is non-zero, penetration where points
/// overlap), velocities where a body moves, sleeping where one sleeps, broad-phase pairs where
/// there is a pair, body marks where there is a body.
std::uint32_t drawn_overlay_flags(const World& world, std::uint32_t flags);

/// One short-named entry per overlay flag of `drawn_flags` (shapes have none), plus motion
/// trails when `trails_on`, in flag order, in the colours of `options.palette`.
std::vector<LegendEntry> legend_entries(const DebugDrawOptions& options, std::uint32_t drawn_flags,
                                        bool trails_on, Color trail_color);

/// The legend's notes for `drawn_flags` (swatch-less entries): what 50 pixels of an impulse or
/// velocity arrow stand for under `camera`, the arrow cut at `max_arrow_pixels`, the
/// penetration magnification and shortest bar, `min_penetration_pixels` (pixels, as drawn).
std::vector<LegendEntry> legend_notes(const DebugDrawOptions& options, std::uint32_t drawn_flags,
                                      const Camera& camera, float max_arrow_pixels, float min_penetration_pixels);

/// Draws the HUD and legend panels of `layout` (translucent) and their text and keys.
void draw_hud(PrimitiveRenderer& renderer, const HudLayout& layout, const ThemePalette& palette);

}  // namespace impulse2d::render

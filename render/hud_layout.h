#pragma once
/// @file hud_layout.h
/// Where the HUD and the legend go on a frame: the HUD is one line in a band along the top
/// edge, the legend a compact block of short entries (several to a row) in a band along the
/// bottom edge. A scene's camera leaves both bands free (`panel_bands`), so neither covers a
/// body, and together they cover at most `panel_area_budget` of the frame.

#include "render/hud.h"

#include <string>
#include <vector>

namespace impulse2d::render {

/// A rectangle in screen pixels (top-left origin, y down). Empty when its width or height is 0.
struct ScreenRect {
  float left = 0.0f;    ///< x of the left edge, pixels
  float top = 0.0f;     ///< y of the top edge, pixels
  float width = 0.0f;   ///< pixels
  float height = 0.0f;  ///< pixels
  /// True when the width or the height is 0 (nothing is drawn there).
  bool empty() const { return width <= 0.0f || height <= 0.0f; }
  /// True when both are non-empty and share some area (touching edges do not overlap).
  bool overlaps(const ScreenRect& other) const;
  /// Width times height, square pixels (0 when empty).
  float area() const { return empty() ? 0.0f : width * height; }
};

/// One legend entry as placed: its key (empty for a note) and where its text starts.
struct PlacedLegendEntry {
  LegendEntry entry;     ///< colour, label, swatch or not
  ScreenRect swatch;     ///< the colour key, pixels (empty for a note)
  float text_left = 0.0f;  ///< x of the text's left edge, pixels
  float text_top = 0.0f;   ///< y of the text's top edge, pixels
};

/// The panels of one frame's HUD and legend, and the text magnification they were laid out for.
struct HudLayout {
  /// The HUD's lines as drawn: the fields that fit joined on the first, then the extra lines.
  std::vector<std::string> hud_lines;
  ScreenRect hud;  ///< the HUD panel, top-left corner (empty without lines)
  std::vector<PlacedLegendEntry> legend_entries;  ///< in reading order
  ScreenRect legend;   ///< the legend panel, bottom-left corner (empty without entries)
  int text_scale = 1;  ///< integer magnification of the font, 1 = 7 px capitals
};

/// The heights of the bands along the top (HUD) and bottom (legend) edges that a scene's
/// camera leaves free, pixels.
struct PanelBands {
  float top = 0.0f;     ///< the HUD's one line, pixels
  float bottom = 0.0f;  ///< `legend_band_rows` legend rows, pixels
};

/// Padding around panel text, in font pixels (multiplied by the text scale).
constexpr float hud_panel_padding = 2.0f;
/// Distance between the tops of consecutive HUD lines or legend rows, font pixels.
constexpr float hud_row_pitch = 11.0f;
/// Width of a legend colour key, font pixels (its height is a capital's).
constexpr float legend_swatch_width = 6.0f;
/// Space between a key and its label, font pixels.
constexpr float legend_swatch_gap = 2.0f;
/// Space between entries of a legend row, font pixels.
constexpr float legend_entry_gap = 6.0f;
/// Legend rows the bottom band holds; a legend needing more grows upwards over the scene.
constexpr int legend_band_rows = 2;
/// The largest fraction of the frame the HUD and legend panels cover together: notes, then
/// HUD fields from the last, are left out to stay within it.
constexpr float panel_area_budget = 0.12f;

/// The bands a frame keeps for the HUD and legend drawn at `text_scale` (`frame_scale` of the
/// frame unless overridden).
PanelBands panel_bands(int text_scale);

/// Lays out `hud` and the legend (`entries`, then `notes` when they fit in the band's rows) on
/// a width x height frame at `text_scale`. The HUD line holds the fields that fit the frame's
/// width (the title without its description first); the legend flows its entries into rows
/// of equal length, as few as the width allows. Notes, then HUD fields from the last (never
/// the title or the step), are left out until both panels cover at most `panel_area_budget`
/// of the frame.
HudLayout layout_hud(int width, int height, const HudText& hud, const std::vector<LegendEntry>& entries,
                     const std::vector<LegendEntry>& notes, int text_scale);

}  // namespace impulse2d::render

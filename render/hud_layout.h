#pragma once
/// @file hud_layout.h
/// Where the HUD text block and the legend go on a frame, so that neither covers the other.

#include <string>
#include <vector>

namespace impulse2d::render {

struct LegendEntry;

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
};

/// The panels of one frame's HUD and legend, and the text magnification they were laid out for.
struct HudLayout {
  /// The HUD's lines as drawn: each given line wrapped at spaces to fit the frame's width.
  std::vector<std::string> hud_lines;
  ScreenRect hud;     ///< the HUD panel, always at the top-left corner (empty without lines)
  ScreenRect legend;  ///< the legend panel (empty without entries)
  int text_scale = 1; ///< integer magnification of the font, 1 = 7 px capitals
};

/// Padding around panel text, in font pixels (multiplied by the text scale).
constexpr float hud_panel_padding = 6.0f;
/// Width of a legend colour key, in font pixels (multiplied by the text scale).
constexpr float legend_swatch_width = 14.0f;

/// `lines` with each line longer than `max_width` font pixels broken where it fits: at the last
/// double space (between HUD fields) that fits, else at the last space; a single word longer
/// than that stays whole.
std::vector<std::string> wrap_lines(const std::vector<std::string>& lines, float max_width);

/// Lays out the HUD (`lines`, top-left, wrapped to the frame's width) and the legend on a
/// frame `width` pixels wide at `text_scale`. The legend goes to the top-right corner when it fits beside the HUD, else to
/// the right edge just under the HUD: it never covers the HUD (it may run off the bottom of a
/// frame too small for both).
HudLayout layout_hud(int width, const std::vector<std::string>& lines,
                     const std::vector<LegendEntry>& legend, int text_scale);

}  // namespace impulse2d::render

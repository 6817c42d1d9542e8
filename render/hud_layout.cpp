/// @file hud_layout.cpp
#include "render/hud_layout.h"

#include "render/easy_font.h"
#include "render/hud.h"

#include <algorithm>

namespace impulse2d::render {

namespace {

// Height of `lines` lines of text, font pixels: the last line ends at its capitals' baseline.
float block_height(std::size_t lines) {
  return font_line_height * static_cast<float>(lines) - (font_line_height - font_cap_height);
}

}  // namespace

bool ScreenRect::overlaps(const ScreenRect& other) const {
  if (empty() || other.empty()) return false;
  return left < other.left + other.width && other.left < left + width && top < other.top + other.height &&
         other.top < top + height;
}

std::vector<std::string> wrap_lines(const std::vector<std::string>& lines, float max_width) {
  // The last position of `separator` in `text` whose text before it fits; npos for none.
  const auto last_fitting = [max_width](const std::string& text, const char* separator) {
    std::size_t cut = text.rfind(separator);
    while (cut != std::string::npos && cut > 0 && text_width(text.substr(0, cut)) > max_width) {
      cut = text.rfind(separator, cut - 1);
    }
    return cut == 0 ? std::string::npos : cut;
  };
  std::vector<std::string> wrapped;
  for (const std::string& line : lines) {
    std::string rest = line;
    while (text_width(rest) > max_width) {
      // Between fields (two spaces) first, so "frame 00042" stays on one line; else between words.
      std::size_t cut = last_fitting(rest, "  ");
      if (cut == std::string::npos) cut = last_fitting(rest, " ");
      if (cut == std::string::npos) break;  // one word wider than the frame
      wrapped.push_back(rest.substr(0, cut));
      rest = rest.substr(rest.find_first_not_of(' ', cut));
    }
    wrapped.push_back(rest);
  }
  return wrapped;
}

HudLayout layout_hud(int width, const std::vector<std::string>& lines,
                     const std::vector<LegendEntry>& legend, int text_scale) {
  HudLayout layout;
  layout.text_scale = std::max(text_scale, 1);
  const float s = static_cast<float>(layout.text_scale);
  if (!lines.empty()) {
    layout.hud_lines = wrap_lines(lines, static_cast<float>(width) / s - 2.0f * hud_panel_padding);
    float text = 0.0f;
    for (const std::string& line : layout.hud_lines) text = std::max(text, text_width(line));
    layout.hud = {0.0f, 0.0f, (text + 2.0f * hud_panel_padding) * s,
                  (block_height(layout.hud_lines.size()) + 2.0f * hud_panel_padding) * s};
  }
  if (legend.empty()) return layout;
  float text = 0.0f;
  for (const LegendEntry& entry : legend) text = std::max(text, text_width(entry.label));
  const float legend_width = (text + legend_swatch_width + 3.0f * hud_panel_padding) * s;
  const float legend_height = (block_height(legend.size()) + 2.0f * hud_panel_padding) * s;
  const float frame_width = static_cast<float>(width);
  const float hud_right = layout.hud.empty() ? 0.0f : layout.hud.left + layout.hud.width;
  const float hud_bottom = layout.hud.empty() ? 0.0f : layout.hud.top + layout.hud.height;
  const float right_edge = std::max(frame_width - legend_width, 0.0f);
  // Beside the HUD when it fits there, else right under it (the upper part of a scene is
  // more often empty than the ground at the bottom); never over the HUD.
  const bool beside = layout.hud.empty() || right_edge >= hud_right;
  layout.legend = {right_edge, beside ? 0.0f : hud_bottom, legend_width, legend_height};
  return layout;
}

}  // namespace impulse2d::render

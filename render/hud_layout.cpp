/// @file hud_layout.cpp
#include "render/hud_layout.h"

#include "render/easy_font.h"

#include <algorithm>
#include <cmath>

namespace impulse2d::render {

namespace {

// Height of a panel of `rows` rows of text, font pixels: a row's glyphs are
// `font_glyph_rows` tall (descenders included).
float panel_height(std::size_t rows) {
  return 2.0f * hud_panel_padding + hud_row_pitch * static_cast<float>(rows - 1) +
         static_cast<float>(font_glyph_rows);
}

std::string joined(const std::vector<std::string>& fields) {
  std::string line;
  for (const std::string& field : fields) line += (line.empty() ? "" : "  ") + field;
  return line;
}

// Width of a legend item, font pixels.
float item_width(const LegendEntry& entry) {
  return (entry.swatch ? legend_swatch_width + legend_swatch_gap : 0.0f) + text_width(entry.label);
}

// The items of each row when items `widths` wide (font pixels) flow into rows at most
// `max_width` font pixels wide (an item wider than that has a row of its own).
std::vector<std::vector<std::size_t>> flow(const std::vector<float>& widths, float max_width) {
  std::vector<std::vector<std::size_t>> rows;
  float row_width = 0.0f;
  for (std::size_t i = 0; i < widths.size(); ++i) {
    const float width = widths[i];
    if (rows.empty() || row_width + legend_entry_gap + width > max_width) {
      rows.push_back({i});
      row_width = width;
    } else {
      rows.back().push_back(i);
      row_width += legend_entry_gap + width;
    }
  }
  return rows;
}

// `items` in as few rows as `max_width` allows, each row as short as that many rows allow: the
// narrowest whole font pixel from the rows' mean width up that keeps the row count. Widths are
// whole font pixels (exact in floats) and flowing wraps greedily, so the row count never grows
// with the width, and that narrowest width is found by bisection.
std::vector<std::vector<std::size_t>> balanced_flow(const std::vector<LegendEntry>& items, float max_width) {
  std::vector<float> widths;
  widths.reserve(items.size());
  for (const LegendEntry& item : items) widths.push_back(item_width(item));
  const std::size_t row_count = flow(widths, max_width).size();
  float total = 0.0f;
  for (const float width : widths) total += width + legend_entry_gap;
  const float narrowest = std::floor(total / static_cast<float>(std::max<std::size_t>(row_count, 1)));
  // Candidate widths narrowest + k for k in [0, candidates): those below max_width.
  const int candidates = narrowest < max_width ? static_cast<int>(std::ceil(max_width - narrowest)) : 0;
  int low = 0;
  int high = candidates;
  while (low < high) {
    const int middle = low + (high - low) / 2;
    if (flow(widths, narrowest + static_cast<float>(middle)).size() <= row_count) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return flow(widths, low < candidates ? narrowest + static_cast<float>(low) : max_width);
}

float row_width(const std::vector<LegendEntry>& items, const std::vector<std::size_t>& row) {
  float width = 0.0f;
  for (const std::size_t i : row) width += item_width(items[i]);
  return width + legend_entry_gap * static_cast<float>(row.size() - 1);
}

// The legend of `items` placed at the bottom-left corner of a width x height frame.
void place_legend(const std::vector<LegendEntry>& items, int width, int height, HudLayout& layout) {
  layout.legend = {};
  layout.legend_entries.clear();
  if (items.empty()) return;
  const float s = static_cast<float>(layout.text_scale);
  const float max_width = static_cast<float>(width) / s - 2.0f * hud_panel_padding;
  const std::vector<std::vector<std::size_t>> rows = balanced_flow(items, max_width);
  float widest = 0.0f;
  for (const std::vector<std::size_t>& row : rows) widest = std::max(widest, row_width(items, row));
  const float panel_h = panel_height(rows.size()) * s;
  layout.legend = {0.0f, static_cast<float>(height) - panel_h, (widest + 2.0f * hud_panel_padding) * s, panel_h};
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const float top = layout.legend.top + (hud_panel_padding + hud_row_pitch * static_cast<float>(r)) * s;
    float x = layout.legend.left + hud_panel_padding * s;
    for (const std::size_t i : rows[r]) {
      PlacedLegendEntry placed;
      placed.entry = items[i];
      if (items[i].swatch) {
        placed.swatch = {x, top, legend_swatch_width * s, font_cap_height * s};
        x += (legend_swatch_width + legend_swatch_gap) * s;
      }
      placed.text_left = x;
      placed.text_top = top;
      layout.legend_entries.push_back(placed);
      x += (text_width(items[i].label) + legend_entry_gap) * s;
    }
  }
}

// The HUD of `fields` (joined on one line) and `extra_lines` at the top-left corner.
void place_hud(const std::vector<std::string>& fields, const std::vector<std::string>& extra_lines,
               HudLayout& layout) {
  layout.hud = {};
  layout.hud_lines.clear();
  if (!fields.empty()) layout.hud_lines.push_back(joined(fields));
  layout.hud_lines.insert(layout.hud_lines.end(), extra_lines.begin(), extra_lines.end());
  if (layout.hud_lines.empty()) return;
  const float s = static_cast<float>(layout.text_scale);
  float text = 0.0f;
  for (const std::string& line : layout.hud_lines) text = std::max(text, text_width(line));
  layout.hud = {0.0f, 0.0f, (text + 2.0f * hud_panel_padding) * s, panel_height(layout.hud_lines.size()) * s};
}

}  // namespace

bool ScreenRect::overlaps(const ScreenRect& other) const {
  if (empty() || other.empty()) return false;
  return left < other.left + other.width && other.left < left + width && top < other.top + other.height &&
         other.top < top + height;
}

PanelBands panel_bands(int text_scale) {
  const float s = static_cast<float>(std::max(text_scale, 1));
  return PanelBands{panel_height(1) * s, panel_height(legend_band_rows) * s};
}

HudLayout layout_hud(int width, int height, const HudText& hud, const std::vector<LegendEntry>& entries,
                     const std::vector<LegendEntry>& notes, int text_scale) {
  HudLayout layout;
  layout.text_scale = std::max(text_scale, 1);
  const float s = static_cast<float>(layout.text_scale);
  const float max_text = static_cast<float>(width) / s - 2.0f * hud_panel_padding;

  // The HUD line: the title without its description when the whole does not fit, then fields
  // from the last left out until it fits (the title and the step always stay).
  std::vector<std::string> fields = hud.fields;
  if (!fields.empty() && text_width(joined(fields)) > max_text) {
    const std::size_t description = fields[0].find(" - ");
    if (description != std::string::npos) fields[0].resize(description);
  }
  while (fields.size() > 2 && text_width(joined(fields)) > max_text) fields.pop_back();

  // The legend: with its notes when they still fit in the band's rows.
  std::vector<LegendEntry> items = entries;
  items.insert(items.end(), notes.begin(), notes.end());
  if (!notes.empty() && balanced_flow(items, max_text).size() > static_cast<std::size_t>(legend_band_rows)) {
    items = entries;
  }

  // Within the area budget: notes go first, then HUD fields from the last.
  const float budget = panel_area_budget * static_cast<float>(width) * static_cast<float>(height);
  place_hud(fields, hud.extra_lines, layout);
  place_legend(items, width, height, layout);
  if (layout.hud.area() + layout.legend.area() > budget && items.size() > entries.size()) {
    items = entries;
    place_legend(items, width, height, layout);
  }
  while (layout.hud.area() + layout.legend.area() > budget && fields.size() > 2) {
    fields.pop_back();
    place_hud(fields, hud.extra_lines, layout);
  }
  return layout;
}

}  // namespace impulse2d::render

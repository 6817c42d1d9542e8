/// @file timeline_strip.cpp
#include "render/timeline_strip.h"

#include "render/easy_font.h"
#include "render/frame_scale.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>

namespace impulse2d::render {

int timeline_height(int width, int height) { return 64 * frame_scale(width, height); }

void draw_timeline(PrimitiveRenderer& renderer, const std::vector<TimelineSample>& samples,
                   std::int64_t current_step, const ThemePalette& palette, int scale) {
  const float s = static_cast<float>(std::max(scale, 1));
  const float width = static_cast<float>(renderer.viewport_width());
  const float height = static_cast<float>(renderer.viewport_height());
  renderer.draw_screen_rect(vec2(0.0f), vec2(width, height), palette.hud_panel);
  if (samples.empty()) return;
  const float text_height = (font_line_height + 4.0f) * s;  // the legend line on top
  const float left = 4.0f * s;
  const float right = width - 4.0f * s;
  const float bottom = 4.0f * s;                // y up: the camera puts world (0, 0) bottom-left
  const float top = height - text_height;
  const std::int64_t first = samples.front().step;
  const std::int64_t last = std::max(samples.back().step, first + 1);
  const auto x_of = [&](std::int64_t step) {
    return left + (right - left) * static_cast<float>(step - first) / static_cast<float>(last - first);
  };
  const auto curve = [&](const std::function<double(const TimelineSample&)>& value, Color color) {
    double low = value(samples.front());
    double high = low;
    for (const TimelineSample& sample : samples) {
      low = std::min(low, value(sample));
      high = std::max(high, value(sample));
    }
    const double span = high > low ? high - low : 1.0;
    const auto y_of = [&](const TimelineSample& sample) {
      return bottom + (top - bottom) * static_cast<float>((value(sample) - low) / span);
    };
    for (std::size_t i = 1; i < samples.size(); ++i) {
      renderer.draw_segment(vec2(x_of(samples[i - 1].step), y_of(samples[i - 1])),
                            vec2(x_of(samples[i].step), y_of(samples[i])), color);
    }
    return std::pair<double, double>(low, high);
  };
  const auto energy = curve([](const TimelineSample& x) { return x.energy; }, timeline_energy_color);
  const auto contacts = curve([](const TimelineSample& x) { return static_cast<double>(x.contacts); },
                              timeline_contacts_color);
  const auto depth = curve([](const TimelineSample& x) { return static_cast<double>(x.max_penetration); },
                           timeline_penetration_color);
  const float marker = x_of(std::clamp(current_step, first, last));
  renderer.draw_segment(vec2(marker, bottom), vec2(marker, top), palette.hud_text);

  char text[160];
  float x = left;
  const auto label = [&](const char* pattern, double low, double high, Color color) {
    std::snprintf(text, sizeof(text), pattern, low, high);
    renderer.draw_screen_rect(vec2(x, 2.0f * s), vec2(10.0f, font_cap_height) * s, color);
    renderer.draw_screen_text(vec2(x + 13.0f * s, 2.0f * s), text, palette.hud_text, scale);
    x += (text_width(text) + 24.0f) * s;
  };
  label("energy %.3g..%.3g J", energy.first, energy.second, timeline_energy_color);
  label("contacts %.0f..%.0f", contacts.first, contacts.second, timeline_contacts_color);
  label("depth %.2g..%.2g m", depth.first, depth.second, timeline_penetration_color);
}

}  // namespace impulse2d::render

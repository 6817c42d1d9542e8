/// @file hud.cpp
#include "render/hud.h"

#include "render/easy_font.h"
#include "render/hud_layout.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <cstdio>

namespace impulse2d::render {

namespace {

constexpr float kScaleBarPixels = 50.0f;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), pattern, value);
  return text;
}

}  // namespace

std::vector<std::string> hud_lines(const HudInfo& info, const HudCounts& counts) {
  std::vector<std::string> lines;
  char frame_text[32];
  std::snprintf(frame_text, sizeof(frame_text), "%05lld", static_cast<long long>(info.frame));
  lines.push_back((info.scene_name.empty() ? std::string("scene") : info.scene_name) + "  frame " + frame_text);
  lines.push_back(format("t = %.3f s", counts.simulated_time) + "  bodies " + std::to_string(counts.body_count) +
                  "  contacts " + std::to_string(counts.contact_count) + " (" +
                  std::to_string(counts.contact_point_count) + " points)" +
                  (counts.sleeping_contact_count > 0
                       ? " + " + std::to_string(counts.sleeping_contact_count) + " sleeping"
                       : std::string()));
  if (info.step_milliseconds || info.frames_per_second) {
    std::string wall_clock;
    if (info.step_milliseconds) wall_clock += format("step %.2f ms", *info.step_milliseconds);
    if (info.frames_per_second) {
      if (!wall_clock.empty()) wall_clock += "  ";
      wall_clock += format("%.1f frames/s", *info.frames_per_second);
    }
    lines.push_back(wall_clock);
  }
  lines.insert(lines.end(), info.extra_lines.begin(), info.extra_lines.end());
  return lines;
}

std::vector<LegendEntry> legend_entries(const DebugDrawOptions& options, const Camera& camera,
                                        bool trails_on, Color trail_color, float max_arrow_pixels,
                                        float min_penetration_pixels) {
  const DebugPalette& p = options.palette;
  const float bar_metres = kScaleBarPixels / camera.pixels_per_metre();
  const auto on = [&](DebugDrawFlag flag) { return (options.flags & flag) != 0; };
  const std::string bar = std::to_string(static_cast<int>(kScaleBarPixels)) + " px = ";

  std::vector<LegendEntry> entries;
  if (on(draw_aabbs)) entries.push_back({p.aabb, "bounding boxes"});
  if (on(draw_contact_points)) entries.push_back({p.contact_point, "contact points"});
  if (on(draw_contact_normals)) {
    entries.push_back({p.contact_normal, "contact normals" + format(" (%.2f m)", options.normal_length)});
  }
  if (on(draw_normal_impulses)) {
    entries.push_back({p.normal_impulse, "normal impulses (" + bar +
                                             format("%.3g N s)", bar_metres / options.impulse_scale)});
  }
  if (on(draw_friction_impulses)) {
    entries.push_back({p.friction_impulse, "friction impulses (" + bar +
                                               format("%.3g N s)", bar_metres / options.impulse_scale)});
  }
  if (on(draw_penetration)) {
    entries.push_back({p.penetration, (options.penetration_scale == 1.0f
                                           ? std::string("penetration (true length")
                                           : "penetration" + format(" (x%.3g", options.penetration_scale)) +
                                          format(", >= %.0f px)", min_penetration_pixels)});
  }
  if (on(draw_velocities)) {
    entries.push_back({p.velocity, "velocities (" + bar + format("%.3g m/s)", bar_metres / options.velocity_scale)});
  }
  if (on(draw_contact_normals) || on(draw_normal_impulses) || on(draw_friction_impulses)) {
    entries.push_back({p.label, format("contact arrows cut at %.0f px, marked //", max_arrow_pixels)});
  }
  if (on(draw_center_of_mass)) entries.push_back({p.center_of_mass, "centres of mass"});
  if (on(draw_sleeping)) entries.push_back({p.sleeping_fill, "sleeping bodies"});
  if (on(draw_broad_phase)) entries.push_back({p.broad_phase_pair, "broad-phase pairs"});
  if (on(draw_body_ids)) entries.push_back({p.label, "body ids"});
  if (trails_on) entries.push_back({trail_color, "motion trails"});
  return entries;
}

void draw_hud(PrimitiveRenderer& renderer, const std::vector<std::string>& lines,
              const std::vector<LegendEntry>& legend, const ThemePalette& palette, int text_scale) {
  const HudLayout layout =
      layout_hud(renderer.viewport_width(), lines, legend, text_scale);
  const float s = static_cast<float>(layout.text_scale);
  const float padding = hud_panel_padding * s;
  if (!layout.hud.empty()) {
    renderer.draw_screen_rect(vec2(layout.hud.left, layout.hud.top), vec2(layout.hud.width, layout.hud.height),
                              palette.hud_panel);
    for (std::size_t i = 0; i < layout.hud_lines.size(); ++i) {
      const vec2 at(layout.hud.left + padding, layout.hud.top + padding + font_line_height * s * static_cast<float>(i));
      renderer.draw_screen_text(at, layout.hud_lines[i], palette.hud_text, layout.text_scale);
    }
  }
  if (layout.legend.empty()) return;
  const ScreenRect& panel = layout.legend;
  renderer.draw_screen_rect(vec2(panel.left, panel.top), vec2(panel.width, panel.height), palette.hud_panel);
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const float top = panel.top + padding + font_line_height * s * static_cast<float>(i);
    Color swatch = legend[i].color;
    swatch.a = std::max(swatch.a, 0.85f);  // keys of translucent overlays still read clearly
    renderer.draw_screen_rect(vec2(panel.left + padding, top), vec2(legend_swatch_width, font_cap_height) * s, swatch);
    renderer.draw_screen_text(vec2(panel.left + 2.0f * padding + legend_swatch_width * s, top), legend[i].label,
                              palette.hud_text, layout.text_scale);
  }
}

}  // namespace impulse2d::render

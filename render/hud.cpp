/// @file hud.cpp
#include "render/hud.h"

#include "core/world.h"
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

// Counts the segments `World::draw` emits (the broad-phase pairs when only they are asked for).
class SegmentCounter final : public DebugDraw {
 public:
  void draw_solid_polygon(const vec2*, int, Color, Color) override {}
  void draw_solid_circle(vec2, float, vec2, Color, Color) override {}
  void draw_segment(vec2, vec2, Color) override { ++segments; }
  void draw_arrow(vec2, vec2, Color) override {}
  void draw_point(vec2, float, Color) override {}
  void draw_text(vec2, const std::string&, Color) override {}
  int segments = 0;
};

}  // namespace

HudText hud_text(const HudInfo& info, const HudCounts& counts) {
  HudText text;
  text.fields.push_back(info.scene_name.empty() ? std::string("scene") : info.scene_name);
  text.fields.push_back("step " + std::to_string(info.step));
  if (info.frame_index && *info.frame_index != info.step) {
    text.fields.push_back("frame " + std::to_string(*info.frame_index));
  }
  text.fields.push_back(format("t = %.3f s", counts.simulated_time));
  text.fields.push_back("bodies " + std::to_string(counts.body_count));
  text.fields.push_back("contacts " + std::to_string(counts.contact_count) + " (" +
                        std::to_string(counts.contact_point_count) + " points)" +
                        (counts.sleeping_contact_count > 0
                             ? " + " + std::to_string(counts.sleeping_contact_count) + " sleeping"
                             : std::string()));
  if (info.step_milliseconds) text.fields.push_back(format("last step %.2f ms", *info.step_milliseconds));
  if (info.frames_per_second) text.fields.push_back(format("%.1f frames/s", *info.frames_per_second));
  text.extra_lines = info.extra_lines;
  return text;
}

HudCounts hud_counts(const World& world) {
  HudCounts counts;
  counts.simulated_time = world.time();
  counts.body_count = world.body_count();
  counts.contact_count = static_cast<int>(world.contacts().size());
  for (const Contact& contact : world.contacts()) counts.contact_point_count += contact.point_count;
  counts.sleeping_contact_count = static_cast<int>(world.sleeping_contacts().size());
  return counts;
}

std::uint32_t drawn_overlay_flags(const World& world, std::uint32_t flags) {
  std::uint32_t drawn = 0;
  const auto scan_contacts = [&drawn](const std::vector<Contact>& contacts) {
    for (const Contact& contact : contacts) {
      if (!contact.enabled) continue;
      for (int i = 0; i < contact.point_count; ++i) {
        const ContactPoint& point = contact.points[i];
        drawn |= draw_contact_points | draw_contact_normals;
        if (point.normal_impulse > 0.0f) drawn |= draw_normal_impulses;
        if (point.tangent_impulse != 0.0f) drawn |= draw_friction_impulses;
        if (point.depth > 0.0f) drawn |= draw_penetration;
      }
    }
  };
  scan_contacts(world.contacts());
  scan_contacts(world.sleeping_contacts());
  const std::vector<BodyId> ids = world.body_ids();
  if (!ids.empty()) drawn |= draw_shapes | draw_aabbs | draw_center_of_mass | draw_body_ids;
  for (const BodyId id : ids) {
    const BodyView body = world.body(id);
    if (body.type != BodyType::Static && length_squared(body.linear_velocity) > 0.0f) drawn |= draw_velocities;
    if (body.type == BodyType::Dynamic && !body.awake) drawn |= draw_sleeping;
  }
  if (world.joint_count() > 0) drawn |= draw_joints;
  if (flags & draw_broad_phase) {
    SegmentCounter pairs;
    DebugDrawOptions options;
    options.flags = draw_broad_phase;
    world.draw(pairs, options);
    if (pairs.segments > 0) drawn |= draw_broad_phase;
  }
  return flags & drawn;
}

std::vector<LegendEntry> legend_entries(const DebugDrawOptions& options, std::uint32_t drawn_flags,
                                        bool trails_on, Color trail_color) {
  const DebugPalette& p = options.palette;
  const auto on = [drawn_flags](DebugDrawFlag flag) { return (drawn_flags & flag) != 0; };
  std::vector<LegendEntry> entries;
  if (on(draw_aabbs)) entries.push_back({p.aabb, "aabb"});
  if (on(draw_contact_points)) entries.push_back({p.contact_point, "point"});
  if (on(draw_contact_normals)) entries.push_back({p.contact_normal, "normal"});
  if (on(draw_normal_impulses)) entries.push_back({p.normal_impulse, "impulse"});
  if (on(draw_friction_impulses)) entries.push_back({p.friction_impulse, "friction"});
  if (on(draw_penetration)) entries.push_back({p.penetration, "depth"});
  if (on(draw_velocities)) entries.push_back({p.velocity, "velocity"});
  if (on(draw_center_of_mass)) entries.push_back({p.center_of_mass, "com"});
  if (on(draw_sleeping)) entries.push_back({p.sleeping_fill, "asleep"});
  if (on(draw_broad_phase)) entries.push_back({p.broad_phase_pair, "pair"});
  if (on(draw_body_ids)) entries.push_back({p.label, "id"});
  if (on(draw_joints)) {
    entries.push_back({p.joint, "joint"});
    entries.push_back({p.joint_reaction, "reaction"});
  }
  if (trails_on) entries.push_back({trail_color, "trail"});
  return entries;
}

std::vector<LegendEntry> legend_notes(const DebugDrawOptions& options, std::uint32_t drawn_flags,
                                      const Camera& camera, float max_arrow_pixels, float min_penetration_pixels) {
  const DebugPalette& p = options.palette;
  const float bar_metres = kScaleBarPixels / camera.pixels_per_metre();
  const auto on = [drawn_flags](std::uint32_t flags) { return (drawn_flags & flags) != 0; };
  const std::string bar = std::to_string(static_cast<int>(kScaleBarPixels)) + " px = ";
  std::vector<LegendEntry> notes;
  // Joint reaction forces are drawn as the impulse of one step, on the impulse arrows' scale.
  if (on(draw_normal_impulses | draw_friction_impulses | draw_joints)) {
    notes.push_back({p.label, "impulse " + bar + format("%.3g N s", bar_metres / options.impulse_scale), false});
  }
  if (on(draw_velocities)) {
    notes.push_back({p.label, "velocity " + bar + format("%.3g m/s", bar_metres / options.velocity_scale), false});
  }
  if (on(draw_penetration)) {
    notes.push_back({p.label,
                     (options.penetration_scale == 1.0f ? std::string("depth true length")
                                                        : "depth" + format(" x%.3g", options.penetration_scale)) +
                         format(", >= %.0f px", min_penetration_pixels),
                     false});
  }
  if (on(draw_contact_normals | draw_normal_impulses | draw_friction_impulses | draw_joints)) {
    notes.push_back({p.label, format("arrows cut at %.0f px //", max_arrow_pixels), false});
  }
  return notes;
}

void draw_hud(PrimitiveRenderer& renderer, const HudLayout& layout, const ThemePalette& palette) {
  const float s = static_cast<float>(layout.text_scale);
  const float padding = hud_panel_padding * s;
  if (!layout.hud.empty()) {
    renderer.draw_screen_rect(vec2(layout.hud.left, layout.hud.top), vec2(layout.hud.width, layout.hud.height),
                              palette.hud_panel);
    for (std::size_t i = 0; i < layout.hud_lines.size(); ++i) {
      const vec2 at(layout.hud.left + padding, layout.hud.top + padding + hud_row_pitch * s * static_cast<float>(i));
      renderer.draw_screen_text(at, layout.hud_lines[i], palette.hud_text, layout.text_scale);
    }
  }
  if (layout.legend.empty()) return;
  const ScreenRect& panel = layout.legend;
  renderer.draw_screen_rect(vec2(panel.left, panel.top), vec2(panel.width, panel.height), palette.hud_panel);
  for (const PlacedLegendEntry& placed : layout.legend_entries) {
    if (!placed.swatch.empty()) {
      Color swatch = placed.entry.color;
      swatch.a = std::max(swatch.a, 0.85f);  // keys of translucent overlays still read clearly
      renderer.draw_screen_rect(vec2(placed.swatch.left, placed.swatch.top),
                                vec2(placed.swatch.width, placed.swatch.height), swatch);
    }
    renderer.draw_screen_text(vec2(placed.text_left, placed.text_top), placed.entry.label, palette.hud_text,
                              layout.text_scale);
  }
}

}  // namespace impulse2d::render

/// @file contact_overlay.cpp
#include "render/contact_overlay.h"

#include "core/world.h"
#include "render/label_placement.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse2d::render {

namespace {

Color faded(Color color, float opacity) {
  color.a *= opacity;
  return color;
}

bool sleeping_dynamic(const World& world, BodyId id) {
  const BodyView body = world.body(id);
  return body.type == BodyType::Dynamic && !body.awake;
}

}  // namespace

bool draw_clamped_arrow(PrimitiveRenderer& renderer, vec2 from, vec2 to, Color color, float max_pixels) {
  const float pixels_per_metre = renderer.camera().pixels_per_metre();
  const float length_pixels = std::sqrt(length_squared(to - from)) * pixels_per_metre;
  if (!(length_pixels > max_pixels)) {
    renderer.draw_arrow(from, to, color);
    return false;
  }
  const vec2 direction = (to - from) / (length_pixels / pixels_per_metre);
  const vec2 tip = from + direction * (max_pixels / pixels_per_metre);
  renderer.draw_arrow(from, tip, color);
  // The break mark: two parallel strokes slanted across the shaft at 60 % of its length.
  const float metre_per_pixel = 1.0f / pixels_per_metre;
  const float stroke = 4.0f * renderer.style().line_width * metre_per_pixel;
  const vec2 across = left_perpendicular(direction);
  const vec2 slant = glm::normalize(across + direction * 0.6f) * stroke;
  const vec2 gap = direction * (2.0f * renderer.style().line_width * metre_per_pixel);
  const vec2 centre = from + direction * (0.6f * max_pixels * metre_per_pixel);
  renderer.draw_segment(centre - gap - slant, centre - gap + slant, color);
  renderer.draw_segment(centre + gap - slant, centre + gap + slant, color);
  return true;
}

void draw_contacts(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                   const ContactOverlayStyle& style, int scale) {
  const std::uint32_t flags = options.flags & contact_overlay_flags;
  if (flags == 0 && !style.feature_ids) return;
  const DebugPalette& palette = options.palette;
  const float s = static_cast<float>(std::max(scale, 1));
  const float pixels_per_metre = renderer.camera().pixels_per_metre();
  const float metre_per_pixel = 1.0f / pixels_per_metre;
  const float max_arrow = style.max_arrow_pixels * s;
  const float min_bar = style.min_penetration_pixels * s * metre_per_pixel;
  const float bar_width = style.penetration_bar_pixels * s;
  const PrimitiveStyle& marks = renderer.style();
  // Where a bar is drawn the arrows stand clear of it: half the bar, half an arrow head and a line.
  const float clear_of_bar = 0.5f * bar_width + 0.5f * marks.arrow_head_width + marks.line_width;
  const auto bar_half_length = [&](const ContactPoint& point) {  // metres; 0 without a bar
    if (!(flags & draw_penetration) || point.depth <= 0.0f) return 0.0f;
    return 0.5f * std::max(point.depth * options.penetration_scale, min_bar);
  };
  const auto for_each_contact = [&](const auto& draw_contact) {
    for (const Contact& contact : world.contacts()) {
      if (!contact.enabled) continue;
      draw_contact(contact, sleeping_dynamic(world, contact.body_a) || sleeping_dynamic(world, contact.body_b));
    }
    for (const Contact& contact : world.sleeping_contacts()) {
      if (contact.enabled) draw_contact(contact, true);
    }
  };
  // Dots and penetration bars first, in a layer of their own: the arrows and ids go over them.
  for_each_contact([&](const Contact& contact, bool dimmed) {
    const float opacity = dimmed ? style.sleeping_opacity : 1.0f;
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      if (flags & draw_contact_points) renderer.draw_point(point.point, 6.0f, faded(palette.contact_point, opacity));
      const float half = bar_half_length(point);
      if (half > 0.0f) {
        renderer.draw_band(point.point - contact.normal * half, point.point + contact.normal * half, bar_width,
                           faded(palette.penetration, opacity));
      }
    }
  });
  renderer.next_layer();
  for_each_contact([&](const Contact& contact, bool dimmed) {
    const float opacity = dimmed ? style.sleeping_opacity : 1.0f;
    const vec2 normal = contact.normal;
    const vec2 tangent = right_perpendicular(normal);
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      const float half = bar_half_length(point);
      const float offset =
          std::max(style.arrow_offset_pixels * s, half > 0.0f ? clear_of_bar : 0.0f) * metre_per_pixel;
      if (flags & draw_contact_normals) {
        const vec2 start = point.point - tangent * offset;
        draw_clamped_arrow(renderer, start, start + normal * options.normal_length,
                           faded(palette.contact_normal, opacity), max_arrow);
      }
      if ((flags & draw_normal_impulses) && point.normal_impulse > 0.0f) {
        const vec2 start = point.point + tangent * offset;
        draw_clamped_arrow(renderer, start, start + normal * (point.normal_impulse * options.impulse_scale),
                           faded(palette.normal_impulse, opacity), max_arrow);
      }
      if ((flags & draw_friction_impulses) && point.tangent_impulse != 0.0f) {
        draw_clamped_arrow(renderer, point.point,
                           point.point + tangent * (point.tangent_impulse * options.impulse_scale),
                           faded(palette.friction_impulse, opacity), max_arrow);
      }
      if (style.feature_ids) {
        // Behind the point (against the normal, where no arrow goes), clear of the bar and dot.
        char text[16];
        std::snprintf(text, sizeof(text), "%X", static_cast<unsigned>(point.feature_id));
        const float clearance = std::max({half * pixels_per_metre, 3.0f * marks.point_scale,
                                          0.5f * marks.arrow_head_width + marks.line_width}) +
                                2.0f * s;
        const vec2 anchor = renderer.camera().world_to_pixel(point.point);
        draw_label_beside(renderer, anchor, vec2(-normal.x, normal.y), clearance, text,
                          faded(palette.label, opacity));
      }
    }
  });
}

}  // namespace impulse2d::render

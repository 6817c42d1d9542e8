/// @file contact_overlay.cpp
#include "render/contact_overlay.h"

#include "core/world.h"
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
  const float metre_per_pixel = 1.0f / renderer.camera().pixels_per_metre();
  const float max_arrow = style.max_arrow_pixels * s;
  const float offset = style.arrow_offset_pixels * s * metre_per_pixel;
  const float min_bar = style.min_penetration_pixels * s * metre_per_pixel;
  const float bar_width = style.penetration_bar_pixels * s;
  auto draw_contact = [&](const Contact& contact, bool dimmed) {
    if (!contact.enabled) return;
    const float opacity = dimmed ? style.sleeping_opacity : 1.0f;
    const vec2 normal = contact.normal;
    const vec2 tangent = right_perpendicular(normal);
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      // The dot first: the penetration bar (narrower, longer) shows across it.
      if (flags & draw_contact_points) {
        renderer.draw_point(point.point, 6.0f * s, faded(palette.contact_point, opacity));
      }
      if ((flags & draw_penetration) && point.depth > 0.0f) {
        const vec2 along = normal * (0.5f * std::max(point.depth * options.penetration_scale, min_bar));
        renderer.draw_band(point.point - along, point.point + along, bar_width, faded(palette.penetration, opacity));
      }
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
      if (style.feature_ids) {
        char text[16];
        std::snprintf(text, sizeof(text), "%X", static_cast<unsigned>(point.feature_id));
        renderer.draw_text(point.point + tangent * (2.0f * offset), text, faded(palette.label, opacity));
      }
      if ((flags & draw_friction_impulses) && point.tangent_impulse != 0.0f) {
        draw_clamped_arrow(renderer, point.point,
                           point.point + tangent * (point.tangent_impulse * options.impulse_scale),
                           faded(palette.friction_impulse, opacity), max_arrow);
      }
    }
  };
  for (const Contact& contact : world.contacts()) {
    draw_contact(contact, sleeping_dynamic(world, contact.body_a) || sleeping_dynamic(world, contact.body_b));
  }
  for (const Contact& contact : world.sleeping_contacts()) draw_contact(contact, true);
}

}  // namespace impulse2d::render

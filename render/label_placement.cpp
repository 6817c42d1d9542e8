/// @file label_placement.cpp
#include "render/label_placement.h"

#include "render/easy_font.h"
#include "render/hud_layout.h"
#include "render/primitive_renderer.h"

#include <cmath>

namespace impulse2d::render {

ScreenRect label_rect_beside(vec2 anchor, vec2 away, float clearance, const std::string& text, int scale) {
  const float length = std::sqrt(length_squared(away));
  const vec2 direction = length > 0.0f ? away / length : vec2(0.70710678f, -0.70710678f);
  const float s = static_cast<float>(scale);
  const vec2 size(text_width(text) * s, font_cap_height * s);
  // The rectangle's half extent along `direction`, so its near side is `clearance` away.
  const float reach = 0.5f * (std::abs(direction.x) * size.x + std::abs(direction.y) * size.y);
  const vec2 middle = anchor + direction * (clearance + reach);
  // Rounded away from the anchor, so that snapping to whole pixels never brings it nearer.
  const float left = direction.x >= 0.0f ? std::ceil(middle.x - 0.5f * size.x) : std::floor(middle.x - 0.5f * size.x);
  const float top = direction.y >= 0.0f ? std::ceil(middle.y - 0.5f * size.y) : std::floor(middle.y - 0.5f * size.y);
  return ScreenRect{left, top, size.x, size.y};
}

void draw_label_beside(PrimitiveRenderer& renderer, vec2 anchor, vec2 away, float clearance,
                       const std::string& text, Color color) {
  const int scale = renderer.style().label_scale;
  const ScreenRect rect = label_rect_beside(anchor, away, clearance, text, scale);
  renderer.draw_screen_text(vec2(rect.left, rect.top), text, color, scale);
}

}  // namespace impulse2d::render

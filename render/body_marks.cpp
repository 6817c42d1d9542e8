/// @file body_marks.cpp
#include "render/body_marks.h"

#include "core/world.h"
#include "render/primitive_renderer.h"

#include <algorithm>

namespace impulse2d::render {

void draw_bounding_boxes(PrimitiveRenderer& renderer, const World& world, Color color) {
  const std::vector<Body>& bodies = world.body_slots();
  for (std::uint32_t slot = 0; slot < bodies.size(); ++slot) {
    if (world.slot_alive(slot)) renderer.draw_box_outline(bodies[slot].aabb.lower, bodies[slot].aabb.upper, color);
  }
}

void draw_body_labels(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                      const BodyLabeler& labeler) {
  const float alpha = std::clamp(options.interpolation_alpha, 0.0f, 1.0f);
  const std::vector<Body>& bodies = world.body_slots();
  for (std::uint32_t slot = 0; slot < bodies.size(); ++slot) {
    if (!world.slot_alive(slot)) continue;
    const Body& body = bodies[slot];
    const vec2 centre = body.previous_position * (1.0f - alpha) + body.transform.position * alpha;
    std::string label = labeler ? labeler(slot) : std::string();
    if (label.empty()) label = std::to_string(slot);
    renderer.draw_text(centre, label, options.palette.label);
  }
}

void draw_highlight(PrimitiveRenderer& renderer, const World& world, std::uint32_t slot, int scale) {
  if (slot >= world.body_slots().size() || !world.slot_alive(slot)) return;
  const Aabb& box = world.body_slots()[slot].aabb;
  const float pixel = 1.0f / renderer.camera().pixels_per_metre();
  const float s = static_cast<float>(std::max(scale, 1));
  for (int ring = 0; ring < 3; ++ring) {
    const float grow = (4.0f + static_cast<float>(ring)) * s * pixel;
    renderer.draw_box_outline(box.lower - vec2(grow), box.upper + vec2(grow), highlight_color);
  }
}

}  // namespace impulse2d::render

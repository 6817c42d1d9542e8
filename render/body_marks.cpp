/// @file body_marks.cpp
#include "render/body_marks.h"

#include "core/world.h"
#include "render/label_placement.h"
#include "render/primitive_renderer.h"

#include <algorithm>

namespace impulse2d::render {

void draw_bounding_boxes(PrimitiveRenderer& renderer, const World& world, Color color) {
  for (const BodyId id : world.body_ids()) {
    const Aabb box = world.body(id).aabb;
    renderer.draw_box_outline(box.lower, box.upper, color);
  }
}

void draw_body_labels(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                      const BodyLabeler& labeler) {
  const float alpha = std::clamp(options.interpolation_alpha, 0.0f, 1.0f);
  const PrimitiveStyle& marks = renderer.style();
  // Clear of the centre-of-mass dot (`World::draw`'s, 5 px at frame scale 1) by two font pixels.
  const float clearance = 2.5f * marks.point_scale + 2.0f * static_cast<float>(marks.label_scale);
  for (const BodyId id : world.body_ids()) {
    const std::uint32_t slot = id.index;
    const BodyView body = world.body(id);
    const vec2 centre = body.previous_position * (1.0f - alpha) + body.transform.position * alpha;
    std::string label = labeler ? labeler(slot) : std::string();
    if (label.empty()) label = std::to_string(slot);
    // Opposite the velocity arrow (screen y points down); up and to the right at rest.
    const vec2 away = body.type == BodyType::Static ? vec2(0.0f)
                                                     : vec2(-body.linear_velocity.x, body.linear_velocity.y);
    draw_label_beside(renderer, renderer.camera().world_to_pixel(centre), away, clearance, label,
                      options.palette.label);
  }
}

void draw_highlight(PrimitiveRenderer& renderer, const World& world, std::uint32_t slot, int scale) {
  const std::vector<BodyId> ids = world.body_ids();
  const auto found = std::find_if(ids.begin(), ids.end(), [slot](BodyId id) { return id.index == slot; });
  if (found == ids.end()) return;
  const Aabb box = world.body(*found).aabb;
  const float pixel = 1.0f / renderer.camera().pixels_per_metre();
  const float s = static_cast<float>(std::max(scale, 1));
  for (int ring = 0; ring < 3; ++ring) {
    const float grow = (4.0f + static_cast<float>(ring)) * s * pixel;
    renderer.draw_box_outline(box.lower - vec2(grow), box.upper + vec2(grow), highlight_color);
  }
}

}  // namespace impulse2d::render

/// @file pyramid.cpp
/// A pyramid of axis-aligned boxes: rows boxes at the bottom, one at the top. Boxes never
/// rotate, so the model leaves rotation off and the narrow phase uses the AABB tests only.
/// The default soft step holds it; the tutorial's solver cannot.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float half_size = 0.5f;  // metres

void build(World& world, const Params& params) {
  const int rows = params.integer("rows");
  add_static_box(world, {0.0f, -0.5f}, {half_size * static_cast<float>(rows) + 3.0f, 0.5f},
                 materials::static_ground());
  for (int row = 0; row < rows; ++row) {
    const int count = rows - row;
    for (int i = 0; i < count; ++i) {
      const float x =
          (static_cast<float>(i) - 0.5f * static_cast<float>(count - 1)) * 2.0f * half_size;
      const float y = half_size + 2.0f * half_size * static_cast<float>(row);
      add_body(world, BodyType::Dynamic, make_box({half_size, half_size}), {x, y},
               materials::wood());
    }
  }
}

}  // namespace

Scene pyramid() {
  Scene scene;
  scene.name = "pyramid";
  scene.description = "a pyramid of axis-aligned boxes, rows at the bottom (default 20: 210 boxes)";
  scene.params = {{"rows", "boxes in the bottom row", 20, 1, 60, true}};
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.model.restitution = false;
  scene.model.sleeping = true;
  scene.view.steps = 600;
  scene.view.frames = "::4";
  scene.view.draw.flags = draw_shapes | draw_sleeping;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file stack.cpp
/// A tall stack of rotating boxes (oriented boxes, so rotation is on and the polygon clipper
/// does the work): a resting stack must not drift by more than the slop.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float half_size = 0.5f;  // metres

void build(World& world, const Params& params) {
  const int height = params.integer("height");
  add_body(world, BodyType::Static, make_oriented_box({6.0f, 0.5f}), {0.0f, -0.5f},
           materials::static_ground());
  for (int i = 0; i < height; ++i) {
    add_body(world, BodyType::Dynamic, make_oriented_box({half_size, half_size}),
             {0.0f, half_size + 2.0f * half_size * static_cast<float>(i)}, materials::wood());
  }
}

}  // namespace

Scene stack() {
  Scene scene;
  scene.name = "stack";
  scene.description = "a tall stack of rotating boxes that must stand still";
  scene.params = {{"height", "boxes in the stack", 15, 1, 80, true}};
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.steps = 600;
  scene.view.frames = "::4";
  scene.view.draw.flags = draw_shapes | draw_contact_points;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file capsules.cpp
/// The shapes a level is made of (issue 31): a floor and a ramp of static segments, capsules
/// lying, standing (they topple and come to rest lying) and tumbling down the ramp, rounded
/// boxes and rounded triangles, and balls, dropped in rows. Every new pair of the jump table
/// meets here: capsule on segment, capsule on capsule, rounded polygon on capsule, ball on
/// rounded corner.
#include "core/world.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

constexpr float floor_half_width = 9.0f;  // metres

Shape rounded_box(float half_width, float half_height, float rounding) {
  const vec2 corners[4] = {{-half_width, -half_height}, {half_width, -half_height}, {half_width, half_height},
                           {-half_width, half_height}};
  return make_rounded_polygon(corners, 4, rounding);
}

Shape rounded_triangle(float size, float rounding) {
  const vec2 corners[3] = {{-size, -0.6f * size}, {size, -0.6f * size}, {0.0f, 0.9f * size}};
  return make_rounded_polygon(corners, 3, rounding);
}

/// The shape of the body in column `column` of a dropped row: capsules of three lengths,
/// rounded boxes and triangles, balls, in turn.
Shape shape_for(int column) {
  switch (column % 5) {
    case 0: return make_capsule({-0.45f, 0.0f}, {0.45f, 0.0f}, 0.22f);
    case 1: return rounded_box(0.35f, 0.25f, 0.08f);
    case 2: return make_capsule({-0.2f, 0.0f}, {0.2f, 0.0f}, 0.3f);
    case 3: return rounded_triangle(0.4f, 0.06f);
    default: return make_circle(0.3f);
  }
}

void build(World& world, const Params& params) {
  const Material ground = materials::static_ground();
  // The level: a floor, two walls and a ramp, all segments.
  add_body(world, BodyType::Static, make_segment({-floor_half_width, 0.0f}, {floor_half_width, 0.0f}), {0.0f, 0.0f},
           ground);
  add_body(world, BodyType::Static, make_segment({0.0f, 0.0f}, {0.0f, 9.0f}), {-floor_half_width, 4.5f}, ground);
  add_body(world, BodyType::Static, make_segment({0.0f, 0.0f}, {0.0f, 9.0f}), {floor_half_width, 4.5f}, ground);
  add_body(world, BodyType::Static, make_segment({-4.0f, 2.2f}, {1.0f, 0.4f}), {-4.5f, 3.0f}, ground);
  // Two capsules stood on end: they topple and come to rest lying.
  add_body(world, BodyType::Dynamic, make_capsule({0.0f, -0.7f}, {0.0f, 0.7f}, 0.2f), {2.0f, 0.9f},
           materials::wood(), 0.05f);
  add_body(world, BodyType::Dynamic, make_capsule({0.0f, -0.5f}, {0.0f, 0.5f}, 0.25f), {6.0f, 0.75f},
           materials::wood(), -0.08f);
  // Rows of mixed shapes dropped from above, each row shifted so they pile unevenly.
  const int rows = static_cast<int>(params.number("rows"));
  int index = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < 8; ++column) {
      const float x = -7.0f + 1.9f * static_cast<float>(column) + (row % 2 == 0 ? 0.0f : 0.8f);
      const float y = 6.0f + 1.3f * static_cast<float>(row);
      const float angle = 0.4f * static_cast<float>((index * 7) % 9) - 1.6f;
      add_body(world, BodyType::Dynamic, shape_for(index), {x, y}, index % 3 == 0 ? materials::rock() : materials::wood(),
               angle);
      ++index;
    }
  }
}

}  // namespace

Scene capsules() {
  Scene scene;
  scene.name = "capsules";
  scene.description =
      "capsules, rounded boxes and triangles and balls dropped on a level of static segments (floor, walls, ramp)";
  scene.params = {{"rows", "rows of 8 dropped bodies", 3, 0, 20, true}};
  scene.model.circles = true;
  scene.model.polygons = true;
  scene.model.capsules = true;
  scene.model.segments = true;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-9.5f, -0.5f}, {9.5f, 10.5f});
  scene.view.steps = 480;
  scene.view.draw.flags = draw_shapes | draw_contact_points | draw_contact_normals;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

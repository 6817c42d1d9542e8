/// @file shape_pairs.cpp
/// Every entry of the narrow phase's 3x3 jump table at work: in row A, column B a body of
/// kind B falls on a body of kind A that rests on a pad. A is created before B, so the pair's
/// first body (the smaller slot) is A and the contact goes through collide[A][B]; the nine
/// cells cover both orders of every pair of kinds.
#include <array>

#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float cell_size = 4.0f;  // metres

Shape shape_of_kind(ShapeType kind) {
  switch (kind) {
    case ShapeType::Circle:
      return make_circle(0.6f);
    case ShapeType::Box:
      return make_box({0.6f, 0.45f});
    case ShapeType::Polygon:
    case ShapeType::Capsule:  // not in this 3x3 grid of the tutorial's kinds (see `capsules`)
    case ShapeType::Segment:
      break;
  }
  const std::array<vec2, 5> pentagon = {vec2{0.6f, -0.45f}, vec2{0.75f, 0.25f}, vec2{0.0f, 0.65f},
                                        vec2{-0.75f, 0.25f}, vec2{-0.6f, -0.45f}};
  return make_polygon(pentagon.data(), static_cast<int>(pentagon.size()));
}

void build(World& world, const Params&) {
  const ShapeType kinds[3] = {ShapeType::Circle, ShapeType::Box, ShapeType::Polygon};
  const Material pad = materials::static_ground();
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) {
      const vec2 origin{cell_size * static_cast<float>(column),
                        -cell_size * static_cast<float>(row)};
      add_static_box(world, origin, {1.5f, 0.2f}, pad);
      add_body(world, BodyType::Dynamic, shape_of_kind(kinds[row]), origin + vec2{0.0f, 0.9f},
               materials::wood());
      add_body(world, BodyType::Dynamic, shape_of_kind(kinds[column]), origin + vec2{0.25f, 2.8f},
               materials::rock(), 0.4f);
    }
  }
}

}  // namespace

Scene shape_pairs() {
  Scene scene;
  scene.name = "shape_pairs";
  scene.description =
      "every pair of the collision jump table: row A (circle, box, polygon) is hit by column B";
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-2.0f, -8.6f}, {10.0f, 3.8f});
  scene.view.steps = 240;
  scene.view.draw.flags = draw_shapes | draw_contact_points | draw_contact_normals;
  scene.view.caption = "rows A: circle box polygon | columns B: circle box polygon";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

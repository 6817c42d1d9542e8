/// @file compound.cpp
/// Bodies of several shapes (issue 31): L-shaped crates of three boxes, hammers with a metal
/// head on a wooden handle (each shape its own material: the hammer turns about its heavy
/// end), T-bars, and dumbbells of two balls on a capsule bar, dropped in rows into a bin that is
/// itself one static body of three boxes, onto a ramp of one static body of two turned boxes.
#include "core/world.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <vector>

namespace impulse2d::demos::scenes {
namespace {

ShapeDef placed(const Shape& shape, vec2 position, float angle, const Material& material) {
  ShapeDef def;
  def.shape = shape;
  def.position = position;
  def.angle = angle;
  def.material = material;
  return def;
}

/// The shapes of the dropped body in column `column` of a row: an L, a hammer, a T, a
/// dumbbell, in turn.
std::vector<ShapeDef> compound_for(int column) {
  const Material wood = materials::wood();
  switch (column % 4) {
    case 0: {  // an L of three 0.5 m squares
      const Shape square = make_oriented_box({0.25f, 0.25f});
      return {placed(square, {0.0f, 0.0f}, 0.0f, wood), placed(square, {0.5f, 0.0f}, 0.0f, wood),
              placed(square, {0.0f, 0.5f}, 0.0f, wood)};
    }
    case 1:  // a hammer: a wooden handle and a metal head
      return {placed(make_oriented_box({0.06f, 0.55f}), {0.0f, 0.0f}, 0.0f, wood),
              placed(make_oriented_box({0.3f, 0.12f}), {0.0f, 0.6f}, 0.0f, materials::metal())};
    case 2:  // a T
      return {placed(make_oriented_box({0.6f, 0.1f}), {0.0f, 0.5f}, 0.0f, wood),
              placed(make_oriented_box({0.1f, 0.4f}), {0.0f, 0.0f}, 0.0f, wood)};
    default:  // a dumbbell: two rubber balls on a capsule bar
      return {placed(make_capsule({-0.45f, 0.0f}, {0.45f, 0.0f}, 0.06f), {0.0f, 0.0f}, 0.0f, wood),
              placed(make_circle(0.22f), {-0.55f, 0.0f}, 0.0f, materials::rock()),
              placed(make_circle(0.22f), {0.55f, 0.0f}, 0.0f, materials::rock())};
  }
}

void build(World& world, const Params& params) {
  const Material ground = materials::static_ground();
  BodyDef level;
  level.type = BodyType::Static;
  // The bin: a floor and two walls, one static body.
  const std::vector<ShapeDef> bin = {placed(make_oriented_box({8.0f, 0.25f}), {0.0f, -0.25f}, 0.0f, ground),
                                     placed(make_oriented_box({0.25f, 4.0f}), {-8.25f, 3.5f}, 0.0f, ground),
                                     placed(make_oriented_box({0.25f, 4.0f}), {8.25f, 3.5f}, 0.0f, ground)};
  world.create_body(level, bin.data(), static_cast<int>(bin.size()));
  // A ramp in the left half, its lip turned up: one static body of two boxes.
  level.position = {-4.5f, 2.5f};
  const std::vector<ShapeDef> ramp = {placed(make_oriented_box({2.2f, 0.1f}), {0.0f, 0.0f}, -0.35f, ground),
                                      placed(make_oriented_box({0.4f, 0.1f}), {2.3f, -0.55f}, 0.3f, ground)};
  world.create_body(level, ramp.data(), static_cast<int>(ramp.size()));
  const int rows = static_cast<int>(params.number("rows"));
  int index = 0;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < 6; ++column) {
      BodyDef def;
      def.position = {-6.0f + 2.4f * static_cast<float>(column) + (row % 2 == 0 ? 0.0f : 0.9f),
                      5.5f + 1.8f * static_cast<float>(row)};
      def.angle = 0.35f * static_cast<float>((index * 5) % 7) - 1.0f;
      const std::vector<ShapeDef> shapes = compound_for(index);
      world.create_body(def, shapes.data(), static_cast<int>(shapes.size()));
      ++index;
    }
  }
}

}  // namespace

Scene compound() {
  Scene scene;
  scene.name = "compound";
  scene.description =
      "bodies of several shapes (L crates, hammers with a metal head, T-bars, dumbbells) dropped into a bin and "
      "onto a ramp that are each one static body of several boxes";
  scene.params = {{"rows", "rows of 6 dropped bodies", 3, 0, 20, true}};
  scene.model.circles = true;
  scene.model.polygons = true;
  scene.model.capsules = true;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-9.0f, -1.0f}, {9.0f, 11.5f});
  scene.view.steps = 480;
  scene.view.draw.flags = draw_shapes | draw_contact_points | draw_contact_normals;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

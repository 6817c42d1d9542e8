/// @file random_polygons.cpp
/// Random convex polygons (3 to 8 vertices) dropped into a box: SAT with reference/incident
/// face clipping, 2-point manifolds and rotation under load.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float half_width = 8.0f;  // inner half width of the container, metres
constexpr float spacing = 2.0f;     // grid spacing of the drop, metres

void build(World& world, const Params& params) {
  const int count = params.integer("count");
  SceneRandom random(static_cast<std::uint32_t>(params.integer("seed")));
  const Material ground = materials::static_ground();
  add_static_box(world, {0.0f, -0.5f}, {half_width + 1.0f, 0.5f}, ground);
  const int per_row = static_cast<int>(2.0f * half_width / spacing) - 1;
  const int rows = (count + per_row - 1) / per_row;
  const float wall_half_height = 0.5f * spacing * static_cast<float>(rows) + 1.0f;
  for (const float side : {-1.0f, 1.0f}) {
    add_static_box(world, {side * (half_width + 0.5f), wall_half_height}, {0.5f, wall_half_height},
                   ground);
  }
  for (int i = 0; i < count; ++i) {
    const int row = i / per_row, column = i % per_row;
    const vec2 position{-half_width + spacing * (static_cast<float>(column) + 1.0f),
                        1.5f + spacing * static_cast<float>(row)};
    // One draw per statement: the order of draws inside one call's arguments is unspecified
    // (GCC and Clang differ). This is the order GCC used, so the scene is unchanged.
    const float angle = random.uniform(0.0f, 6.2831853f);
    const float radius = random.uniform(0.4f, 0.9f);
    const Shape shape = random_convex_polygon(random, radius);
    add_body(world, BodyType::Dynamic, shape, position, materials::wood(), angle);
  }
}

}  // namespace

Scene random_polygons() {
  Scene scene;
  scene.name = "random_polygons";
  scene.description = "random convex polygons (3-8 vertices) dropped into a box";
  scene.params = {
      {"count", "number of polygons", 80, 1, 2000, true},
      {"seed", "random seed of shapes, sizes and angles", 7, 0, 4294967295.0, true},
  };
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.sleeping = true;
  scene.view.steps = 600;
  scene.view.frames = "::4";
  scene.view.draw.flags = draw_shapes | draw_contact_points;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file ball_pit.cpp
/// A ball pit: 1000+ circles poured into a container. Sort-and-sweep keeps the broad phase
/// O(n log n); balls do not need to spin, so rotation is off; sleeping lets the settled pit
/// cost little.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float half_width = 12.0f;  // inner half width of the container, metres
constexpr float spacing = 0.62f;     // grid spacing of the initial pour, metres

void build(World& world, const Params& params) {
  const int balls = params.integer("balls");
  SceneRandom random(static_cast<std::uint32_t>(params.integer("seed")));
  const Material ground = materials::static_ground();
  add_static_box(world, {0.0f, -0.5f}, {half_width + 1.0f, 0.5f}, ground);
  const int per_row = static_cast<int>(2.0f * half_width / spacing) - 1;
  const int rows = (balls + per_row - 1) / per_row;
  const float wall_half_height = 0.5f * spacing * static_cast<float>(rows) + 1.0f;
  for (const float side : {-1.0f, 1.0f}) {
    add_static_box(world, {side * (half_width + 0.5f), wall_half_height}, {0.5f, wall_half_height},
                   ground);
  }
  const Material rubber{"Rubber", 0.4f, 0.3f, 0.8f, 0.6f};
  for (int i = 0; i < balls; ++i) {
    const int row = i / per_row, column = i % per_row;
    const float x =
        -half_width + spacing * (static_cast<float>(column) + 1.0f) + random.uniform(-0.05f, 0.05f);
    const float y = 0.5f + spacing * static_cast<float>(row);
    add_body(world, BodyType::Dynamic, make_circle(random.uniform(0.2f, 0.3f)), {x, y}, rubber);
  }
}

}  // namespace

Scene ball_pit() {
  Scene scene;
  scene.name = "ball_pit";
  scene.description = "a ball pit of 1000+ circles poured into a container";
  scene.params = {
      {"balls", "number of balls", 1200, 1, 20000, true},
      {"seed", "random seed of sizes and jitter", 3, 0, 4294967295.0, true},
  };
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.model.sleeping = true;
  scene.view.steps = 600;
  scene.view.frames = "::4";
  scene.view.draw.flags = draw_shapes | draw_sleeping;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

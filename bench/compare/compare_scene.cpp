/// @file compare_scene.cpp
#include "bench/compare/compare_scene.h"

#include <algorithm>

namespace impulse2d::compare {
namespace {

Material material(const char* name, float density, float friction) {
  return Material{name, density, 0.0f, friction, friction};
}

void add_static_box(CompareScene& scene, vec2 center, vec2 half_extents) {
  BodySpec spec{BodyDef{}, make_oriented_box(half_extents)};
  spec.def.type = BodyType::Static;
  spec.def.position = center;
  spec.def.material = material("Ground", 0.0f, 0.6f);
  scene.bodies.push_back(spec);
}

void add_dynamic(CompareScene& scene, vec2 position, const Shape& shape) {
  BodySpec spec{BodyDef{}, shape};
  spec.def.position = position;
  spec.def.material = material("Body", 1.0f, 0.6f);
  scene.bodies.push_back(spec);
  ++scene.dynamic_count;
}

// Box2D v3's pyramid layout (shared/benchmarks.c): rows of boxes of half-size `extent`,
// touching, the base row centred on `center_x` less half a box, resting on `base_y`; the last
// box made is the top.
void add_pyramid(CompareScene& scene, int rows, float extent, float center_x, float base_y) {
  const Shape box = make_oriented_box({extent, extent});
  for (int i = 0; i < rows; ++i) {
    const float y = (2.0f * static_cast<float>(i) + 1.0f) * extent + base_y;
    for (int j = i; j < rows; ++j) {
      const float x = (static_cast<float>(i) + 1.0f) * extent +
                      2.0f * static_cast<float>(j - i) * extent + center_x;
      add_dynamic(scene, {x, y}, box);
    }
  }
  scene.tops.push_back(static_cast<int>(scene.bodies.size()) - 1);
}

}  // namespace

CompareScene pyramid_scene(const std::string& name, int rows, int steps) {
  CompareScene scene;
  scene.name = name;
  scene.description = std::to_string(rows) + "-row pyramid on a static ground (Box2D v3 large_pyramid layout)";
  scene.steps = steps;
  add_static_box(scene, {0.0f, -1.0f}, {100.0f, 1.0f});
  const float extent = 0.5f;
  add_pyramid(scene, rows, extent, -extent * static_cast<float>(rows), 0.0f);
  return scene;
}

CompareScene many_pyramids_scene(const std::string& name, int count, int columns, int rows,
                                 int steps) {
  CompareScene scene;
  scene.name = name;
  scene.description = std::to_string(count) + (count == 1 ? " pyramid of " : " pyramids of ") + std::to_string(rows) +
                      " rows, " + std::to_string(columns) +
                      " to a ground (Box2D v3 many_pyramids layout)";
  scene.steps = steps;
  const float extent = 0.5f;
  const int pyramid_rows = (count + columns - 1) / columns;
  const float ground_step = 2.0f * extent * (static_cast<float>(rows) + 1.0f);
  const float ground_width = 2.0f * extent * static_cast<float>(columns) * (static_cast<float>(rows) + 1.0f);
  const float thickness = 0.1f;
  for (int i = 0; i < pyramid_rows; ++i) {
    add_static_box(scene, {0.0f, static_cast<float>(i) * ground_step - thickness},
                   {0.5f * ground_width, thickness});
  }
  const float base_width = 2.0f * extent * static_cast<float>(rows);
  for (int k = 0; k < count; ++k) {
    const int row = k / columns;
    const int column = k % columns;
    const float center_x = -0.5f * ground_width +
                           static_cast<float>(column) * (base_width + 2.0f * extent) + 2.0f * extent;
    add_pyramid(scene, rows, extent, center_x - 0.5f, static_cast<float>(row) * ground_step);
  }
  return scene;
}

const std::vector<ScalingSize>& scaling_sizes() {
  static const std::vector<ScalingSize> sizes = [] {
    std::vector<ScalingSize> list;
    for (const int pyramids : {18, 36, 91, 182, 364, 910, 1820}) list.push_back({pyramids, 55 * pyramids});
    return list;
  }();
  return sizes;
}

CompareScene scaling_scene(int pyramids, int steps) {
  CompareScene scene =
      many_pyramids_scene("scaling_" + std::to_string(55 * pyramids), pyramids, 20, 10, steps);
  scene.scaling = true;
  return scene;
}

CompareScene ball_pit_scene(const std::string& name, int balls, int columns, int steps) {
  CompareScene scene;
  scene.name = name;
  scene.description = std::to_string(balls) + " balls dropped into an open box";
  scene.steps = steps;
  scene.judge = Judge::Pit;
  const float radius = 0.25f;
  const float spacing = 2.2f * radius;
  const float inner_half_width = 0.5f * spacing * (static_cast<float>(columns) + 1.0f);
  const int rows = (balls + columns - 1) / columns;
  const float height = spacing * static_cast<float>(rows) + 2.0f;
  const float wall = 0.5f;
  add_static_box(scene, {0.0f, -wall}, {inner_half_width + 2.0f * wall, wall});
  add_static_box(scene, {-inner_half_width - wall, 0.5f * height}, {wall, 0.5f * height});
  add_static_box(scene, {inner_half_width + wall, 0.5f * height}, {wall, 0.5f * height});
  scene.container.lower = {-inner_half_width, 0.0f};
  scene.container.upper = {inner_half_width, height};
  const Shape ball = make_circle(radius);
  for (int k = 0; k < balls; ++k) {
    const int row = k / columns;
    const int column = k % columns;
    // Odd rows shifted by half a radius, so the columns do not stand on each other.
    const float shift = row % 2 == 0 ? 0.0f : 0.5f * radius;
    add_dynamic(scene,
                {-inner_half_width + spacing * (static_cast<float>(column) + 1.0f) - 0.25f * radius + shift,
                 radius + spacing * static_cast<float>(row)},
                ball);
  }
  return scene;
}

CompareScene rain_scene(const std::string& name, int count, int steps) {
  CompareScene scene;
  scene.name = name;
  scene.description = std::to_string(count) +
                      " boxes and balls raining onto a field, recycled when they fall off";
  scene.steps = steps;
  scene.judge = Judge::Rain;
  add_static_box(scene, {0.0f, -0.5f}, {20.0f, 0.5f});
  const int columns = 80;
  const float left = -30.0f;
  const float spacing = 60.0f / static_cast<float>(columns - 1);
  const Shape box = make_oriented_box({0.25f, 0.25f});
  const Shape ball = make_circle(0.25f);
  for (int k = 0; k < count; ++k) {
    const int row = k / columns;
    const int column = k % columns;
    add_dynamic(scene,
                {left + spacing * static_cast<float>(column), 5.0f + 1.0f * static_cast<float>(row)},
                k % 2 == 0 ? box : ball);
  }
  const int rows = (count + columns - 1) / columns;
  scene.recycle.below = -20.0f;
  scene.recycle.left = left;
  scene.recycle.right = -left;
  scene.recycle.top = std::max(30.0f, 5.0f + static_cast<float>(rows));
  scene.recycle.speed = 5.0f;
  scene.recycle.slots = columns;
  // In 12 steps (0.2 s) a body put back at 5 m/s falls 1.2 m: clear of the next one.
  scene.recycle.spacing_steps = 12;
  return scene;
}

}  // namespace impulse2d::compare

/// @file rope_bridge.cpp
/// A bridge of `planks` planks hinged end to end between two posts, `slack` longer than the
/// gap, laid out on a circular arc and left to sag into a catenary; `crates` boxes then drop
/// on it.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

constexpr float span = 14.0f;          // metres between the hinges on the posts
constexpr float deck_height = 5.0f;    // height of those hinges, metres
constexpr float plank_half_height = 0.06f;

void build(World& world, const Params& params) {
  const int planks = params.integer("planks");
  const float length = span * (1.0f + static_cast<float>(params.number("slack")));
  const int crates = params.integer("crates");
  add_static_box(world, {0.0f, -0.5f}, {10.0f, 0.5f}, materials::static_ground());
  const BodyId left = add_static_box(world, {-0.5f * span - 0.3f, 0.5f * deck_height}, {0.3f, 0.5f * deck_height},
                                     materials::static_ground());
  const BodyId right = add_static_box(world, {0.5f * span + 0.3f, 0.5f * deck_height},
                                      {0.3f, 0.5f * deck_height}, materials::static_ground());
  // The arc through both hinges whose length is `length`: sin(phi) / phi = span / length.
  double low = 1e-6, high = 3.14159;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    if (std::sin(mid) / mid > span / length) low = mid; else high = mid;
  }
  const float phi = static_cast<float>(0.5 * (low + high));
  const float radius = 0.5f * span / std::sin(phi);
  const vec2 center(0.0f, deck_height + radius * std::cos(phi));
  const auto joint_point = [&](int i) {
    const float t = -phi + 2.0f * phi * static_cast<float>(i) / static_cast<float>(planks);
    return center + radius * vec2(std::sin(t), -std::cos(t));
  };
  BodyId previous = left;
  for (int i = 0; i < planks; ++i) {
    const vec2 from = joint_point(i);
    const vec2 to = joint_point(i + 1);
    const vec2 along = to - from;
    const BodyId plank = add_body(world, BodyType::Dynamic,
                                  make_oriented_box({0.5f * glm::length(along), plank_half_height}),
                                  0.5f * (from + to), materials::wood(), std::atan2(along.y, along.x));
    add_hinge(world, previous, plank, from);
    previous = plank;
  }
  add_hinge(world, previous, right, joint_point(planks));
  for (int i = 0; i < crates; ++i) {
    const float x = -3.0f + 6.0f * static_cast<float>(i) / static_cast<float>(std::max(crates - 1, 1));
    add_body(world, BodyType::Dynamic, make_oriented_box({0.35f, 0.35f}), {x, 8.0f + 1.2f * static_cast<float>(i)},
             materials::wood());
  }
}

}  // namespace

Scene rope_bridge() {
  Scene scene;
  scene.name = "rope_bridge";
  scene.description = "20 planks hinged between two posts sag into a catenary; crates drop on them";
  scene.params = {
      {"planks", "planks in the bridge", 20, 2, 100, true},
      {"slack", "extra length over the gap, as a fraction of it", 0.1, 0.001, 1, false},
      {"crates", "boxes dropped on the bridge", 2, 0, 10, true},
  };
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-8.5f, 0.0f}, {8.5f, 10.0f});
  scene.view.steps = 600;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file pendulum.cpp
/// A rod on a hinge released from `angle` degrees, and beside it a double pendulum (two rods,
/// two hinges) released from the same angle: the single one swings periodically, the double
/// one soon turns chaotic.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

constexpr float rod_length = 2.0f;  // metres
constexpr float rod_half_width = 0.08f;

// A rod hanging from `pivot` at `angle` (radians from straight down, counter-clockwise).
BodyId add_rod(World& world, vec2 pivot, float angle) {
  const vec2 down(std::sin(angle), -std::cos(angle));
  return add_body(world, BodyType::Dynamic, make_oriented_box({rod_half_width, 0.5f * rod_length}),
                  pivot + down * (0.5f * rod_length), materials::wood(), angle);
}

vec2 rod_end(vec2 pivot, float angle) { return pivot + vec2(std::sin(angle), -std::cos(angle)) * rod_length; }

void build(World& world, const Params& params, bool single, bool twin) {
  const float angle = radians(static_cast<float>(params.number("angle")));
  const BodyId ceiling = add_body(world, BodyType::Static, make_oriented_box({7.0f, 0.15f}), {0.0f, 0.15f},
                                  materials::static_ground());
  if (single) {
    const vec2 pivot(twin ? -3.5f : 0.0f, 0.0f);
    add_hinge(world, ceiling, add_rod(world, pivot, angle), pivot);
  }
  if (twin) {
    const vec2 pivot(single ? 3.0f : 0.0f, 0.0f);
    const BodyId upper = add_rod(world, pivot, angle);
    add_hinge(world, ceiling, upper, pivot);
    const vec2 elbow = rod_end(pivot, angle);
    const BodyId lower = add_rod(world, elbow, angle);
    add_hinge(world, upper, lower, elbow);
  }
}

Scene pendulum_scene(const char* name, const char* description, bool single, bool twin) {
  Scene scene;
  scene.name = name;
  scene.description = description;
  scene.params = {{"angle", "release angle from straight down, degrees", 90, -179, 179, false}};
  scene.model.polygons = true;
  scene.model.friction = false;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = single && twin ? make_bounds({-7.0f, -5.0f}, {7.0f, 0.5f})
                                            : make_bounds({-5.0f, -5.0f}, {5.0f, 0.5f});
  scene.view.steps = 600;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = [single, twin](World& world, const Params& params) { build(world, params, single, twin); };
  return scene;
}

}  // namespace

Scene pendulum() {
  return pendulum_scene("pendulum", "a rod on a hinge released from the horizontal", true, false);
}

Scene double_pendulum() {
  return pendulum_scene("double_pendulum", "a single and a double pendulum released from the same angle", true,
                        true);
}

}  // namespace impulse2d::demos::scenes

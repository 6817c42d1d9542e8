/// @file car.cpp
/// A car on bumpy ground: a chassis with two wheels on wheel joints (suspension springs of
/// `hertz`), the rear wheel driven by a motor. The camera follows the chassis.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float wheel_radius = 0.4f;

void build(World& world, const Params& params) {
  const Material ground = materials::static_ground();
  add_static_box(world, {20.0f, -0.5f}, {30.0f, 0.5f}, ground);
  // Bumps: large discs buried but for 15 cm, gentle humps (and never whole in view, so the
  // legend band over the ground hides no body).
  for (int i = 0; i < 8; ++i) {
    const float x = 4.0f + 3.5f * static_cast<float>(i);
    const float radius = i % 2 == 0 ? 1.5f : 1.0f;
    add_body(world, BodyType::Static, make_circle(radius), {x, -radius + 0.15f}, ground);
  }
  const Material body{"Chassis", 2.0f, 0.1f, 0.6f, 0.5f};
  const Material tyre{"Tyre", 1.0f, 0.1f, 1.0f, 0.9f};
  const vec2 chassis_at(0.0f, 1.2f);
  const BodyId chassis =
      add_body(world, BodyType::Dynamic, make_oriented_box({1.3f, 0.3f}), chassis_at, body);
  const float hertz = static_cast<float>(params.number("hertz"));
  const float speed = static_cast<float>(params.number("speed"));
  for (int i = 0; i < 2; ++i) {
    const vec2 at(i == 0 ? -0.9f : 0.9f, wheel_radius + 0.05f);
    const BodyId wheel = add_body(world, BodyType::Dynamic, make_circle(wheel_radius), at, tyre);
    WheelJointDef def;
    def.body_a = chassis;
    def.body_b = wheel;
    def.local_anchor_a = local_point(world, chassis, at);
    def.local_axis_a = {0.0f, 1.0f};
    def.hertz = hertz;
    def.damping_ratio = 0.7f;
    def.enable_limit = true;
    def.lower_translation = -0.25f;
    def.upper_translation = 0.25f;
    def.enable_motor = i == 0;
    def.motor_speed = -speed;
    def.max_motor_torque = 20.0f;
    world.create_joint(def);
  }
}

}  // namespace

Scene car() {
  Scene scene;
  scene.name = "car";
  scene.description = "a car on wheel joints (sprung, rear-wheel drive) over bumpy ground";
  scene.params = {
      {"hertz", "suspension frequency, Hz", 4, 0.5, 30, false},
      {"speed", "rear motor speed, rad/s", 8, 0, 60, false},
  };
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::Follow;
  scene.view.camera.follow_body = 9;  // the chassis: after the ground and the 8 bumps
  scene.view.camera.center = {0.0f, 1.2f};
  scene.view.camera.pixels_per_metre = 60.0f;
  scene.view.steps = 600;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file terrain_chain.cpp
/// A hill-climb track (issue 31): one open chain of 0.5 m links over smooth hills and a dip,
/// a car on wheel joints driving over the hills, and behind it a floating rock that is a closed
/// loop (listed clockwise: solid inside) with balls and boxes rolling and sliding off it and
/// along the track. The track is one surface: nothing catches on the 120 seams of its links.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <vector>

namespace impulse2d::demos::scenes {
namespace {

constexpr float track_start = -20.0f;  // metres
constexpr float link_length = 0.5f;    // metres
constexpr int track_links = 120;
constexpr float wheel_radius = 0.4f;   // metres

/// A smooth hump of height `height` (m; negative: a dip) and half width `half_width` (m)
/// centred at `centre`: height (1 - t^2)^2 for |t| < 1, t = (x - centre) / half_width.
float hump(float x, float centre, float half_width, float height) {
  const float t = (x - centre) / half_width;
  if (t <= -1.0f || t >= 1.0f) return 0.0f;
  const float u = 1.0f - t * t;
  return height * u * u;
}

/// The track's height (m) at `x`: flat, then three hills with a dip between.
float track_height(float x) {
  return hump(x, 5.0f, 4.0f, 1.2f) + hump(x, 14.0f, 5.0f, 2.0f) + hump(x, 20.5f, 2.5f, -0.6f) +
         hump(x, 27.0f, 3.0f, 0.9f);
}

void add_car(World& world, vec2 at, float speed) {
  const Material body{"Chassis", 2.0f, 0.1f, 0.6f, 0.5f};
  const Material tyre{"Tyre", 1.0f, 0.1f, 1.0f, 0.9f};
  const BodyId chassis = add_body(world, BodyType::Dynamic, make_oriented_box({1.1f, 0.25f}), at, body);
  for (int i = 0; i < 2; ++i) {
    const vec2 wheel_at = at + vec2(i == 0 ? -0.8f : 0.8f, -0.55f);
    const BodyId wheel = add_body(world, BodyType::Dynamic, make_circle(wheel_radius), wheel_at, tyre);
    WheelJointDef def;
    def.body_a = chassis;
    def.body_b = wheel;
    def.local_anchor_a = local_point(world, chassis, wheel_at);
    def.local_axis_a = {0.0f, 1.0f};
    def.hertz = 4.0f;
    def.damping_ratio = 0.7f;
    def.enable_limit = true;
    def.lower_translation = -0.25f;
    def.upper_translation = 0.25f;
    def.enable_motor = true;  // both wheels driven: the steepest slope is 32 degrees
    def.motor_speed = -speed;
    def.max_motor_torque = 40.0f;
    world.create_joint(def);
  }
}

void build(World& world, const Params& params) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  std::vector<vec2> track;
  for (int i = 0; i <= track_links; ++i) {
    const float x = track_start + link_length * static_cast<float>(i);
    track.push_back({x, track_height(x)});
  }
  world.create_chain(ground, track.data(), static_cast<int>(track.size()), false);
  // A floating rock behind the car: a closed loop listed clockwise, so its front sides face out.
  const vec2 rock[] = {{-1.5f, 0.0f}, {-0.8f, 0.7f}, {0.9f, 0.6f}, {1.6f, -0.1f}, {0.6f, -0.6f}, {-0.9f, -0.5f}};
  ground.position = {-17.0f, 3.0f};
  world.create_chain(ground, rock, 6, true);
  add_car(world, {-12.0f, 1.0f}, static_cast<float>(params.number("speed")));
  // Balls and boxes dropped on the rock: they roll and slide off it and on along the track
  // behind the car, across its seams.
  for (int i = 0; i < 5; ++i) {
    const vec2 at(-18.2f + 0.75f * static_cast<float>(i), 4.6f + 0.8f * static_cast<float>(i % 2));
    if (i % 2 == 0) {
      add_body(world, BodyType::Dynamic, make_circle(0.3f), at, materials::rock());
    } else {
      add_body(world, BodyType::Dynamic, make_oriented_box({0.25f, 0.25f}), at, materials::wood(), 0.3f);
    }
  }
}

}  // namespace

Scene terrain_chain() {
  Scene scene;
  scene.name = "terrain_chain";
  scene.description =
      "a hill-climb track: one chain of 120 links over hills, a loop rock, a car driving over them and "
      "balls and boxes rolling and sliding down across the seams";
  scene.params = {{"speed", "wheel motor speed, rad/s", 8, 0, 40, false}};
  scene.model.circles = true;
  scene.model.polygons = true;
  scene.model.segments = true;
  scene.model.restitution = true;
  scene.view.camera.mode = CameraSpec::Mode::Follow;
  scene.view.camera.follow_body = track_links + 6;  // the chassis: after the track and the rock
  scene.view.camera.center = {-12.0f, 1.0f};
  scene.view.camera.pixels_per_metre = 32.0f;
  scene.view.steps = 720;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

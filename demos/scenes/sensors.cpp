/// @file sensors.cpp
/// Events on show (issue 32): `balls` balls fall one after another through a sensor box (each
/// reports a sensor begin on entering it and an end on leaving it, and moves as if it were not
/// there) onto the ground, and beside them a bouncy ball bounces (a hit at each landing, the
/// burst shrinking with the approach speed). Drawn with the events overlay.
#include "core/world.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float ball_radius = 0.4f;  // metres
constexpr vec2 sensor_center{-2.0f, 4.0f};
constexpr vec2 sensor_half_extents{2.2f, 0.7f};

BodyId add_ball(World& world, vec2 position, const Material& material) {
  BodyDef def;
  def.position = position;
  def.material = material;
  def.enable_hit_events = true;
  return world.create_body(def, make_circle(ball_radius));
}

void build(World& world, const Params& params) {
  const int balls = static_cast<int>(params.integer("balls"));
  add_static_box(world, {0.0f, -0.5f}, {6.5f, 0.5f}, materials::static_ground());
  BodyDef sensor;
  sensor.type = BodyType::Static;
  sensor.position = sensor_center;
  sensor.is_sensor = true;
  world.create_body(sensor, make_box(sensor_half_extents));
  // Spread across the sensor and dropped from ever higher, so they pass it one at a time.
  for (int i = 0; i < balls; ++i) {
    const float across = balls > 1 ? static_cast<float>(i) / static_cast<float>(balls - 1) : 0.5f;
    const float x = sensor_center.x + (across - 0.5f) * 2.0f * (sensor_half_extents.x - ball_radius);
    add_ball(world, {x, 6.5f + 1.5f * static_cast<float>(i)}, materials::wood());
  }
  add_ball(world, {3.5f, 4.75f}, materials::bouncy_ball());
}

}  // namespace

Scene sensors() {
  Scene scene;
  scene.name = "sensors";
  scene.description =
      "balls fall through a sensor box (sensor begin and end) and a ball bounces (hits), drawn with "
      "the events overlay";
  scene.params = {{"balls", "balls dropped through the sensor", 3, 1, 6, true}};
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-7.0f, -1.0f}, {7.0f, 10.0f});
  scene.view.steps = 360;
  scene.view.draw.flags = draw_shapes | draw_events;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

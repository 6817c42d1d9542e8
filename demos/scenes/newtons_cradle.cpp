/// @file newtons_cradle.cpp
/// Newton's cradle without strings: in zero gravity, `moving` balls hit a row of resting,
/// touching balls head-on with restitution 1. Exactly, only as many balls leave the far end
/// as came in, at the same speed; a sequential impulse solver only approximates this, which
/// is what the scene is for.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float radius = 0.5f;  // metres
constexpr float gap = 2.0f;     // distance the moving balls travel before the hit, metres

void build(World& world, const Params& params) {
  const int balls = params.integer("balls");
  const int moving = params.integer("moving");
  const float speed = static_cast<float>(params.number("speed"));
  const Material steel{"Steel", 1.2f, 1.0f, 0.0f, 0.0f};
  for (int i = 0; i < balls; ++i) {
    const bool incoming = i < moving;
    BodyDef def;
    def.material = steel;
    def.position = {2.0f * radius * static_cast<float>(i) - (incoming ? gap : 0.0f), 0.0f};
    def.linear_velocity = {incoming ? speed : 0.0f, 0.0f};
    world.create_body(def, make_circle(radius));
  }
}

}  // namespace

Scene newtons_cradle() {
  Scene scene;
  scene.name = "newtons_cradle";
  scene.description = "Newton's cradle in zero gravity: balls hit a touching row with e = 1";
  scene.params = {
      {"balls", "balls in all", 5, 2, 20, true},
      {"moving", "balls coming in from the left", 1, 1, 19, true},
      {"speed", "speed of the incoming balls, m/s", 4, 0.1, 50, false},
  };
  scene.model.circles = true;
  scene.model.rotation = false;
  scene.model.friction = false;
  scene.settings.gravity = {0.0f, 0.0f};
  scene.settings.restitution_threshold = 0.0f;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-5.0f, -2.5f}, {12.0f, 2.5f});
  scene.view.steps = 180;
  scene.view.draw.flags = draw_shapes | draw_velocities;
  scene.view.draw.velocity_scale = 0.4f;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

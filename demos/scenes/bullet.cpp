/// @file bullet.cpp
/// Tunnelling and continuous collision: three small balls fly at a thin wall. The slow one
/// (top) is seen overlapping the wall and bounces. The fast plain one (middle) moves farther
/// than the wall is thick in one step, is never seen overlapping it, and passes through. The
/// fast one marked `is_bullet` (bottom) is swept over its step (the model turns CCD on), stops
/// at the time of impact and bounces back. Speculative contacts are off in this scene (margin
/// 0): with the default margin the fast plain ball is caught a step ahead too, and the
/// contrast between discrete and swept collision it exists to show would vanish.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float bullet_radius = 0.1f;  // metres
constexpr float start_x = -7.5f;       // metres

void build(World& world, const Params& params) {
  const float thickness = static_cast<float>(params.number("wall"));
  add_static_box(world, {0.0f, 0.0f}, {0.5f * thickness, 5.0f}, materials::static_ground());
  const Material lead{"Lead", 11.3f, 0.5f, 0.0f, 0.0f};
  const float slow = static_cast<float>(params.number("slow"));
  const float fast = static_cast<float>(params.number("speed"));
  struct Lane {
    float y;
    float speed;
    bool swept;
  };
  for (const Lane& lane :
       {Lane{3.0f, slow, false}, Lane{0.0f, fast, false}, Lane{-3.0f, fast, true}}) {
    BodyDef def;
    def.material = lead;
    def.is_bullet = lane.swept;
    def.position = {start_x, lane.y};
    def.linear_velocity = {lane.speed, 0.0f};
    world.create_body(def, make_circle(bullet_radius));
  }
}

}  // namespace

Scene bullet() {
  Scene scene;
  scene.name = "bullet";
  scene.description =
      "balls at a thin wall: slow bounces, fast tunnels, fast with CCD (is_bullet) is stopped";
  scene.params = {
      {"speed", "speed of the two fast balls, m/s", 300, 1, 5000, false},
      {"slow", "speed of the slow ball, m/s", 15, 0.1, 100, false},
      {"wall", "wall thickness, metres", 0.1, 0.01, 2, false},
  };
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.model.friction = false;
  scene.model.ccd = true;
  scene.settings.gravity = {0.0f, 0.0f};
  scene.settings.speculative_margin = 0.0f;  // discrete collision, the contrast to CCD
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-9.0f, -5.5f}, {9.0f, 5.5f});
  scene.view.steps = 90;
  scene.view.frames = "::1";
  scene.view.draw.flags = draw_shapes | draw_velocities | draw_contact_points;
  scene.view.draw.velocity_scale = 0.02f;
  scene.view.caption = "top: slow | middle: fast, tunnels | bottom: fast + CCD";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

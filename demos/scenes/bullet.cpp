/// @file bullet.cpp
/// Tunnelling: two small balls fly at a thin wall. The slow one (top) bounces; the fast one
/// (bottom) moves farther than the wall is thick in one step, is never seen overlapping it, and
/// passes through. The core has no continuous collision yet, so the model declares ccd off;
/// once CCD exists this scene shows it with the switch on.
#include "core/world.h"
#include "demos/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float bullet_radius = 0.1f;  // metres
constexpr float start_x = -7.5f;       // metres

void build(World& world, const Params& params) {
  const float thickness = static_cast<float>(params.number("wall"));
  add_static_box(world, {0.0f, 0.0f}, {0.5f * thickness, 5.0f}, materials::static_ground());
  const Material lead{"Lead", 11.3f, 0.5f, 0.0f, 0.0f};
  const float speeds[2] = {static_cast<float>(params.number("slow")),
                           static_cast<float>(params.number("speed"))};
  for (int i = 0; i < 2; ++i) {
    BodyDef def;
    def.material = lead;
    def.is_bullet = true;
    def.position = {start_x, i == 0 ? 2.0f : -2.0f};
    def.linear_velocity = {speeds[i], 0.0f};
    world.create_body(def, make_circle(bullet_radius));
  }
}

}  // namespace

Scene bullet() {
  Scene scene;
  scene.name = "bullet";
  scene.description =
      "a fast bullet tunnels through a thin wall (no CCD in the core yet); a slow one bounces";
  scene.params = {
      {"speed", "speed of the fast bullet, m/s", 300, 1, 5000, false},
      {"slow", "speed of the slow bullet, m/s", 15, 0.1, 100, false},
      {"wall", "wall thickness, metres", 0.1, 0.01, 2, false},
  };
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.model.friction = false;
  scene.model.ccd = false;
  scene.settings.gravity = {0.0f, 0.0f};
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-9.0f, -5.5f}, {9.0f, 5.5f});
  scene.view.steps = 90;
  scene.view.frames = "::1";
  scene.view.draw.flags = draw_shapes | draw_velocities | draw_contact_points;
  scene.view.caption = "top: slow, bounces | bottom: fast, tunnels";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file heavy_on_light.cpp
/// Mass ratios that plain Gauss-Seidel iterations cannot hold: a 1000 kg plank bridging two
/// 1 kg boxes, and a 300 kg crate on one 1 kg box, beside a 1 kg box that starts 0.3 m deep in
/// the ground. Shock propagation (`WorldSettings::shock_propagation`) keeps the light boxes
/// from being squeezed out; the deep box is pushed out at most `max_correction` per position
/// pass; a box dropped on its corner rocks to rest; with sleeping on, everything sleeps.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float light_half = 0.5f;       // half-size of the 1 kg boxes, metres
constexpr float start_depth = 0.3f;      // how deep the right box starts in the ground, metres

// A material of `density` (kg/m^2) with the friction of wood on wood (mu_s 0.6, mu_d 0.4).
Material with_density(const char* name, float density) {
  return Material{name, density, 0.0f, 0.6f, 0.4f};
}

void build(World& world, const Params&) {
  const Material ground{"Ground", 0.0f, 0.0f, 0.6f, 0.4f};
  add_body(world, BodyType::Static, make_oriented_box({8.0f, 0.25f}), {0.0f, -0.25f}, ground);
  const Material light = with_density("Light 1 kg", 1.0f);
  const Shape light_box = make_oriented_box({light_half, light_half});
  // 1:1000: a 2.4 m x 0.5 m plank of 1000 kg on two light boxes 0.2 m apart.
  add_body(world, BodyType::Dynamic, light_box, {-4.6f, light_half}, light);
  add_body(world, BodyType::Dynamic, light_box, {-3.4f, light_half}, light);
  add_body(world, BodyType::Dynamic, make_oriented_box({1.2f, 0.25f}), {-4.0f, 1.25f},
           with_density("Plank 1000 kg", 1000.0f / 1.2f));
  // 1:300: a 1 m crate of 300 kg on one light box.
  add_body(world, BodyType::Dynamic, light_box, {0.0f, light_half}, light);
  add_body(world, BodyType::Dynamic, light_box, {0.0f, 1.5f}, with_density("Crate 300 kg", 300.0f));
  // A light box created 0.3 m into the ground.
  add_body(world, BodyType::Dynamic, light_box, {4.0f, light_half - start_depth}, light);
  // A light box dropped on its corner: it rocks to rest, turning faster than it moves, so its
  // angular speed decides when it sleeps.
  const BodyId rocking =
      add_body(world, BodyType::Dynamic, light_box, {6.5f, 1.0f}, light);
  world.set_transform(rocking, {6.5f, 1.0f}, 0.3f);
}

}  // namespace

Scene heavy_on_light() {
  Scene scene;
  scene.name = "heavy_on_light";
  scene.description =
      "a 1000 kg plank on two 1 kg boxes and a 300 kg crate on one stand (shock propagation); "
      "a box created 0.3 m deep in the ground is pushed out; a box dropped on its corner rocks to "
      "rest; all fall asleep";
  scene.model.polygons = true;
  scene.model.rotation = true;
  scene.model.restitution = false;
  scene.model.sleeping = true;
  scene.view.steps = 300;
  scene.view.frames = "::2";
  scene.view.draw.flags = draw_shapes | draw_sleeping | draw_contact_points;
  scene.view.caption = "heavy_on_light: 1:1000 | 1:300 | created 0.3 m deep | rocking";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file materials.cpp
/// The seven tutorial materials (part 2) side by side: a ball of each dynamic material falls
/// on a perfectly elastic pad, so with the tutorial's min(eA, eB) rule each bounce shows the
/// ball's own restitution (apex heights e^(2k) h). The seventh, Static, has density 0: its
/// ball hangs where it was placed.
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float column_spacing = 3.0f;  // metres
constexpr float ball_radius = 0.6f;     // metres

void build(World& world, const Params& params) {
  const float height = static_cast<float>(params.number("height"));
  const Material pad{"Pad", 0.0f, 1.0f, 0.0f, 0.0f};  // static, elastic, frictionless
  const std::vector<Material> all = materials::all();
  for (std::size_t i = 0; i < all.size(); ++i) {
    const float x = (static_cast<float>(i) - 3.0f) * column_spacing;
    add_static_box(world, {x, -0.3f}, {1.2f, 0.3f}, pad);
    const bool is_static = !(all[i].density > 0.0f);
    const float y = is_static ? 0.5f * height : height;
    add_body(world, is_static ? BodyType::Static : BodyType::Dynamic, make_circle(ball_radius),
             {x, y + ball_radius}, all[i]);
  }
}

}  // namespace

Scene materials() {
  Scene scene;
  scene.name = "materials";
  scene.description =
      "material showcase: Rock, Wood, Metal, BouncyBall, SuperBall, Pillow bounce on elastic "
      "pads; Static (density 0) hangs still";
  scene.params = {{"height", "drop height above the pads, metres", 8, 1, 30, false}};
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.rotation = false;
  scene.model.friction = false;
  scene.settings.restitution_mixing = RestitutionMixing::Minimum;
  scene.settings.restitution_threshold = 0.2f;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-11.0f, -1.0f}, {11.0f, 10.0f});
  scene.view.steps = 480;
  scene.view.caption = "Rock Wood Metal BouncyBall SuperBall Pillow Static";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

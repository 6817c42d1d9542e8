/// @file friction_ramp.cpp
/// Coulomb friction on an incline: a block holds iff tan(theta) <= mu_s, otherwise it slides
/// with a = g (sin(theta) - mu_d cos(theta)). Four parallel ramps at the same angle, stacked
/// along their normal, carry a block each: mu_s just above tan(theta) (holds), then just
/// below it with three dynamic coefficients (creeps, slides, slides fast). The ramps' friction is
/// high and mixing takes the minimum, so each contact uses the block's own coefficients.
#include <cmath>
#include <string>

#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float ramp_half_length = 10.0f;     // metres
constexpr float ramp_half_thickness = 0.25f;  // metres
constexpr float ramp_spacing = 3.0f;          // distance between parallel ramps, metres
constexpr vec2 block_half{0.5f, 0.35f};       // metres

void build(World& world, const Params& params) {
  const float theta = radians(static_cast<float>(params.number("angle")));
  const float margin = static_cast<float>(params.number("margin"));
  // The engine's own cos/sin (not libm's), so the scene is the same on every machine.
  const CosSin slope = cos_sin(theta);
  const float tan_theta = slope.sine / slope.cosine;
  const Material ramp{"Ramp", 0.0f, 0.0f, 2.0f, 2.0f};
  const vec2 along{slope.cosine, -slope.sine};  // down the ramp, to the right
  const vec2 up{slope.sine, slope.cosine};      // the ramp's outward normal

  // {mu_s, mu_d} per ramp, top to bottom.
  const float below = tan_theta - margin;
  const vec2 coefficients[4] = {{tan_theta + margin, below},
                                {below, below},
                                {below, 0.6f * tan_theta},
                                {below, 0.3f * tan_theta}};
  for (int i = 0; i < 4; ++i) {
    const vec2 center = -ramp_spacing * static_cast<float>(i) * up;
    add_body(world, BodyType::Static, make_oriented_box({ramp_half_length, ramp_half_thickness}),
             center, ramp, -theta);
    const Material block{"mu_s " + std::to_string(coefficients[i].x), 0.3f, 0.0f, coefficients[i].x,
                         coefficients[i].y};
    const vec2 position =
        center - (ramp_half_length - 1.5f) * along + (ramp_half_thickness + block_half.y) * up;
    add_body(world, BodyType::Dynamic, make_oriented_box(block_half), position, block, -theta);
  }
}

}  // namespace

Scene friction_ramp() {
  Scene scene;
  scene.name = "friction_ramp";
  scene.description =
      "boxes on ramps: mu_s just above tan(theta) holds; just below slides, farther for "
      "smaller mu_d";
  scene.params = {
      {"angle", "ramp angle, degrees", 30, 5, 60, false},
      {"margin", "how far mu_s sits above / below tan(angle)", 0.05, 0.005, 0.3, false},
  };
  scene.model.polygons = true;
  // Rotating boxes, as a user's would be: each block rests on two contact points with unequal
  // normal impulses, the case where a per-point static/dynamic rule goes wrong.
  scene.model.rotation = true;
  scene.model.restitution = false;
  scene.settings.friction_mixing = FrictionMixing::Minimum;
  scene.view.steps = 180;
  scene.view.draw.flags = draw_shapes | draw_velocities;
  scene.view.caption = "mu_s: tan+m | tan-m (mu_d = mu_s, 0.6 tan, 0.3 tan)";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

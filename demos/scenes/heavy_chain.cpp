/// @file heavy_chain.cpp
/// A chain of `links` light links hinged end to end from a ceiling, with a load of `ratio`
/// (default 100) times one link's mass at its end; released from the horizontal, it swings.
/// Mass ratios like this stretch a sequential solver's joints.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

constexpr float link_length = 0.4f;
constexpr float link_half_width = 0.05f;

void build(World& world, const Params& params) {
  const int links = params.integer("links");
  const float ratio = static_cast<float>(params.number("ratio"));
  const Material light{"Link", 1.0f, 0.05f, 0.4f, 0.3f};
  const BodyId ceiling =
      add_body(world, BodyType::Static, make_oriented_box({1.0f, 0.15f}), {0.0f, 0.15f}, materials::static_ground());
  const vec2 start(0.0f, 0.0f);
  BodyId previous = ceiling;
  for (int i = 0; i < links; ++i) {
    const vec2 from = start + vec2(link_length * static_cast<float>(i), 0.0f);
    const BodyId link = add_body(world, BodyType::Dynamic, make_oriented_box({0.5f * link_length, link_half_width}),
                                 from + vec2(0.5f * link_length, 0.0f), light);
    add_hinge(world, previous, link, from);
    previous = link;
  }
  // The load: a square `ratio` times a link's mass at the same density.
  const float link_area = link_length * 2.0f * link_half_width;
  const float half_side = 0.5f * std::sqrt(ratio * link_area);
  const vec2 end = start + vec2(link_length * static_cast<float>(links), 0.0f);
  const BodyId load = add_body(world, BodyType::Dynamic, make_oriented_box({half_side, half_side}),
                               end + vec2(half_side, 0.0f), light);
  add_hinge(world, previous, load, end);
}

}  // namespace

Scene heavy_chain() {
  Scene scene;
  scene.name = "heavy_chain";
  scene.description = "a chain of light links swinging a load 100 times a link's mass";
  scene.params = {
      {"links", "links in the chain", 15, 1, 100, true},
      {"ratio", "load mass / link mass", 100, 1, 10000, false},
  };
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-8.0f, -8.5f}, {8.0f, 0.5f});
  scene.view.steps = 600;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file catapult.cpp
/// A see-saw catapult: a plank hinged on a wedge (joint limits of +-0.35 rad) with a ball on
/// its low end; a crate `ratio` times the ball's mass drops on the high end, the plank slams
/// into its limit and throws the ball.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

constexpr float pivot_height = 1.2f;
constexpr float half_length = 3.0f;
constexpr float limit = 0.35f;

void build(World& world, const Params& params) {
  const Material ground = materials::static_ground();
  add_static_box(world, {-4.0f, -0.5f}, {14.0f, 0.5f}, ground);
  const vec2 wedge[3] = {{-0.6f, 0.0f}, {0.6f, 0.0f}, {0.0f, pivot_height - 0.12f}};
  const BodyId fulcrum = world.create_body([&] {
    BodyDef def;
    def.type = BodyType::Static;
    def.material = ground;
    vec2 centroid;
    make_polygon(wedge, 3, &centroid);
    def.position = centroid;
    return def;
  }(), make_polygon(wedge, 3));
  // The plank rests on its left end at the upper limit.
  const vec2 pivot(0.0f, pivot_height);
  const vec2 along(std::cos(limit), std::sin(limit));
  const BodyId plank = add_body(world, BodyType::Dynamic, make_oriented_box({half_length, 0.1f}), pivot,
                                materials::wood(), limit);
  add_hinge(world, fulcrum, plank, pivot, -2.0f * limit, 0.0f);
  const float ball_radius = 0.3f;
  const vec2 normal(-along.y, along.x);
  add_body(world, BodyType::Dynamic, make_circle(ball_radius), pivot - along * 2.6f + normal * (0.1f + ball_radius),
           materials::wood());
  const float ratio = static_cast<float>(params.number("ratio"));
  // Same density as the ball: the side gives the mass ratio.
  const float ball_area = 3.14159265f * ball_radius * ball_radius;
  const float half_side = 0.5f * std::sqrt(ratio * ball_area);
  add_body(world, BodyType::Dynamic, make_oriented_box({half_side, half_side}),
           pivot + along * 2.4f + vec2(0.0f, 4.0f), materials::wood(), limit);
}

}  // namespace

Scene catapult() {
  Scene scene;
  scene.name = "catapult";
  scene.description = "a see-saw catapult: a heavy crate drops on a hinged plank and throws a ball";
  scene.params = {{"ratio", "crate mass / ball mass", 8, 1, 100, false}};
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-16.0f, -0.5f}, {6.0f, 10.0f});
  scene.view.steps = 360;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

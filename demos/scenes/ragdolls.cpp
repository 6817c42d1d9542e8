/// @file ragdolls.cpp
/// A pile of ragdolls: `count` ten-part figures (head, torso, arms and legs in two parts each,
/// nine hinges with joint limits) dropped at different angles into a box.
#include "core/world.h"
#include "demos/joint_helpers.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"

#include <cmath>

namespace impulse2d::demos::scenes {
namespace {

// One part in the ragdoll's own frame (upright, torso centre at the origin).
struct Part {
  vec2 center;
  vec2 half;  // half extents; x = radius for the head
};

// The hinges: part indices, the anchor in the ragdoll's frame and the joint angle range.
struct Hinge {
  int a, b;
  vec2 anchor;
  float lower, upper;
};

void add_ragdoll(World& world, const Transform& pose) {
  const Part parts[10] = {
      {{0.0f, 0.0f}, {0.2f, 0.35f}},      // 0 torso
      {{0.0f, 0.55f}, {0.18f, 0.0f}},     // 1 head
      {{-0.3f, 0.13f}, {0.07f, 0.2f}},    // 2 left upper arm
      {{0.3f, 0.13f}, {0.07f, 0.2f}},     // 3 right upper arm
      {{-0.3f, -0.29f}, {0.06f, 0.19f}},  // 4 left forearm
      {{0.3f, -0.29f}, {0.06f, 0.19f}},   // 5 right forearm
      {{-0.1f, -0.57f}, {0.08f, 0.22f}},  // 6 left thigh
      {{0.1f, -0.57f}, {0.08f, 0.22f}},   // 7 right thigh
      {{-0.1f, -1.02f}, {0.07f, 0.22f}},  // 8 left shin
      {{0.1f, -1.02f}, {0.07f, 0.22f}},   // 9 right shin
  };
  const Hinge hinges[9] = {
      {0, 1, {0.0f, 0.37f}, -0.6f, 0.6f},   {0, 2, {-0.3f, 0.33f}, -2.5f, 0.5f},
      {0, 3, {0.3f, 0.33f}, -0.5f, 2.5f},   {2, 4, {-0.3f, -0.09f}, -2.2f, 0.0f},
      {3, 5, {0.3f, -0.09f}, 0.0f, 2.2f},   {0, 6, {-0.1f, -0.35f}, -1.5f, 0.6f},
      {0, 7, {0.1f, -0.35f}, -1.5f, 0.6f},  {6, 8, {-0.1f, -0.79f}, 0.0f, 2.0f},
      {7, 9, {0.1f, -0.79f}, 0.0f, 2.0f},
  };
  const float angle = std::atan2(pose.rotation.sine, pose.rotation.cosine);
  BodyId ids[10];
  const Material flesh{"Flesh", 1.0f, 0.05f, 0.6f, 0.5f};
  for (int i = 0; i < 10; ++i) {
    const Shape shape = i == 1 ? make_circle(parts[i].half.x) : make_oriented_box(parts[i].half);
    ids[i] = add_body(world, BodyType::Dynamic, shape, pose.apply(parts[i].center), flesh, angle);
  }
  for (const Hinge& hinge : hinges) {
    add_hinge(world, ids[hinge.a], ids[hinge.b], pose.apply(hinge.anchor), hinge.lower, hinge.upper);
  }
}

void build(World& world, const Params& params) {
  const int count = params.integer("count");
  const Material ground = materials::static_ground();
  add_static_box(world, {0.0f, -0.5f}, {4.5f, 0.5f}, ground);
  add_static_box(world, {-4.25f, 4.0f}, {0.25f, 4.0f}, ground);
  add_static_box(world, {4.25f, 4.0f}, {0.25f, 4.0f}, ground);
  for (int i = 0; i < count; ++i) {
    const float angle = 0.9f * static_cast<float>(i) - 0.6f;
    const float x = i % 3 == 0 ? -1.5f : (i % 3 == 1 ? 1.5f : 0.0f);
    add_ragdoll(world, Transform{vec2(x, 2.0f + 2.2f * static_cast<float>(i)), Rotation::from_angle(angle)});
  }
}

}  // namespace

Scene ragdolls() {
  Scene scene;
  scene.name = "ragdolls";
  scene.description = "ragdolls of ten parts and nine limited hinges dropped into a pile";
  scene.params = {{"count", "ragdolls", 6, 1, 40, true}};
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-5.0f, -0.5f}, {5.0f, 15.0f});
  scene.view.steps = 600;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file mouse_drag.cpp
/// A box dragged by a mouse joint: the target moves along a loop (as a hand with a mouse
/// would), the box follows on the joint's spring (`hertz`) up to its force limit, bumping a
/// second box.
#include "core/world.h"
#include "demos/scene_helpers.h"
#include "scene/scene.h"
#include "scene/script_state.h"
#include "scene/step_script.h"

#include <cmath>
#include <memory>

namespace impulse2d::demos::scenes {
namespace {

// The target's path: rests, then a loop over the ground, seconds -> metres.
vec2 target_at(double seconds) {
  if (seconds < 0.5) return {-3.0f, 1.5f};
  const double t = seconds - 0.5;
  return {static_cast<float>(-3.0 + 3.0 * (1.0 - std::cos(0.8 * t))),
          static_cast<float>(1.5 + 1.5 * std::sin(1.6 * t))};
}

class DragScript : public StepScript {
 public:
  void before_step(World& world, std::int64_t) override {
    for (const JointId id : world.joint_ids()) {
      if (world.joint_type(id) == JointType::Mouse) world.set_mouse_target(id, target_at(world.time()));
    }
  }
  // The target follows the world's time: the state is the version.
  std::vector<std::uint8_t> save_state() const override { return ScriptStateWriter(state_version).bytes(); }
  void restore_state(World&, const std::vector<std::uint8_t>& bytes) override {
    ScriptStateReader(bytes, "script mouse_drag", state_version).finish();
  }

 private:
  static constexpr std::uint32_t state_version = 1;
};

void build(World& world, const Params& params) {
  const BodyId ground = add_static_box(world, {0.0f, -0.5f}, {6.0f, 0.5f}, materials::static_ground());
  const BodyId box =
      add_body(world, BodyType::Dynamic, make_oriented_box({0.4f, 0.4f}), {-3.0f, 0.4f}, materials::wood());
  add_body(world, BodyType::Dynamic, make_oriented_box({0.5f, 0.5f}), {1.0f, 0.5f}, materials::wood());
  MouseJointDef def;
  def.body_a = ground;
  def.body_b = box;
  def.local_anchor_b = {0.25f, 0.25f};  // grabbed off-centre, so it swings
  def.target = target_at(0.0);
  def.hertz = static_cast<float>(params.number("hertz"));
  def.damping_ratio = 0.7f;
  def.max_force = 200.0f * world.body(box).mass;
  world.create_joint(def);
}

}  // namespace

Scene mouse_drag() {
  Scene scene;
  scene.name = "mouse_drag";
  scene.description = "a box dragged along a loop by a mouse joint";
  scene.params = {{"hertz", "mouse joint frequency, Hz", 5, 0.5, 60, false}};
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.restitution = false;
  scene.view.camera.mode = CameraSpec::Mode::FitBounds;
  scene.view.camera.bounds = make_bounds({-6.0f, -0.5f}, {6.0f, 4.5f});
  scene.view.steps = 480;
  scene.view.draw.flags = draw_shapes | draw_joints;
  scene.build = build;
  scene.script = [](const Params&) { return std::make_unique<DragScript>(); };
  return scene;
}

}  // namespace impulse2d::demos::scenes

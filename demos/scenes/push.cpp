/// @file push.cpp
/// Static against dynamic friction under a push: three rotating 1x1 boxes (mu_s 0.5,
/// mu_d 0.3) on flat ground, each pushed at its centre by a constant horizontal force. The
/// top one gets (1 - m) mu_s W and stays put; the middle one (1 + m) mu_s W breaks loose and
/// accelerates at g ((1 + m) mu_s - mu_d), already faster than static friction would allow;
/// the bottom one gets twice mu_s W. A box starts to move iff F > mu_s W; then
/// a = (F - mu_d W) / m.
#include <memory>

#include "core/world.h"
#include "scene/scene.h"
#include "scene/script_state.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float lane_spacing = 3.0f;  // metres between the grounds of the three lanes
constexpr int lane_count = 3;  // lane i's box is the i-th dynamic body in slot order

const Material& box_material() {
  static const Material material{"Box mu_s 0.5 mu_d 0.3", 1.0f, 0.0f, 0.5f, 0.3f};
  return material;
}

// Force on lane i's box as a multiple of mu_s W.
float push_ratio(const Params& params, int lane) {
  const float margin = static_cast<float>(params.number("margin"));
  const float ratios[lane_count] = {1.0f - margin, 1.0f + margin, 2.0f};
  return ratios[lane];
}

void build(World& world, const Params&) {
  const Material ground{"Ground mu_s 0.5 mu_d 0.3", 0.0f, 0.0f, 0.5f, 0.3f};
  for (int lane = 0; lane < lane_count; ++lane) {
    const float floor = -lane_spacing * static_cast<float>(lane);
    add_body(world, BodyType::Static, make_oriented_box({12.0f, 0.25f}), {3.0f, floor - 0.25f}, ground);
    add_body(world, BodyType::Dynamic, make_oriented_box({0.5f, 0.5f}), {-6.0f, floor + 0.5f},
             box_material());
  }
}

/// Applies each lane's constant push before every step.
class PushScript final : public StepScript {
 public:
  explicit PushScript(const Params& params) {
    for (int lane = 0; lane < lane_count; ++lane) ratios_[lane] = push_ratio(params, lane);
  }
  void before_step(World& world, std::int64_t) override {
    int lane = 0;
    for (const BodyId id : world.body_ids()) {
      const BodyView body = world.body(id);
      if (body.type != BodyType::Dynamic || lane >= lane_count) continue;
      const float weight = body.mass * -world.settings().gravity.y;
      world.apply_force_to_center(id, {ratios_[lane] * box_material().static_friction * weight, 0.0f});
      ++lane;
    }
  }
  // The pushes depend on the parameters alone: the state is the version.
  std::vector<std::uint8_t> save_state() const override { return ScriptStateWriter(state_version).bytes(); }
  void restore_state(World&, const std::vector<std::uint8_t>& bytes) override {
    ScriptStateReader(bytes, "script push", state_version).finish();
  }

 private:
  static constexpr std::uint32_t state_version = 1;
  float ratios_[lane_count] = {};
};

}  // namespace

Scene push() {
  Scene scene;
  scene.name = "push";
  scene.description =
      "rotating boxes pushed along flat ground: (1 - m) mu_s W holds, (1 + m) mu_s W and "
      "2 mu_s W slide at (F - mu_d W) / m";
  scene.params = {{"margin", "how far the two lower pushes sit around mu_s W", 0.05, 0.005, 0.5, false}};
  scene.model.polygons = true;
  scene.model.rotation = true;
  scene.model.restitution = false;
  scene.settings.friction_mixing = FrictionMixing::Minimum;
  scene.view.steps = 120;
  scene.view.draw.flags = draw_shapes | draw_velocities | draw_contact_points;
  scene.view.caption = "push: (1-m) mu_s W | (1+m) mu_s W | 2 mu_s W";
  scene.build = build;
  scene.script = [](const Params& params) { return std::make_unique<PushScript>(params); };
  return scene;
}

}  // namespace impulse2d::demos::scenes

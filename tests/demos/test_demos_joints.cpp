// The built-in scenes with joints (issue 30): the ragdoll pile keeps its energy bounded, no
// body leaves the scene, reruns are bit-identical; the rope bridge sags as the catenary of its
// length; scene-file joints are created with world anchors and follow their events.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/world.h"
#include "demos/scene_registry.h"
#include "scene/scene_loader.h"
#include "scene/scene_run.h"
#include "scene/usage_error.h"

using namespace impulse2d;
using namespace impulse2d::demos;

namespace {

double kinetic_and_potential(const World& world) {
  double energy = 0.0;
  const float g = -world.settings().gravity.y;
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    if (body.type != BodyType::Dynamic) continue;
    const double v2 = static_cast<double>(body.linear_velocity.x) * body.linear_velocity.x +
                      static_cast<double>(body.linear_velocity.y) * body.linear_velocity.y;
    energy += 0.5 * body.mass * v2 + 0.5 * body.inertia * body.angular_velocity * body.angular_velocity +
              body.mass * g * body.transform.position.y;
  }
  return energy;
}

}  // namespace

TEST(DemoJoints, EveryJointSceneIsRegisteredWithJoints) {
  for (const char* name : {"pendulum", "double_pendulum", "rope_bridge", "car", "ragdolls", "catapult",
                           "heavy_chain", "mouse_drag"}) {
    const Scene* scene = find_builtin_scene(name);
    ASSERT_NE(scene, nullptr) << name;
    SceneRun run(*scene, Params(scene->params));
    EXPECT_GT(run.world().joint_count(), 0) << name;
    for (int i = 0; i < 60; ++i) run.step();
    EXPECT_TRUE(run.divergences().empty()) << name;
  }
}

TEST(DemoJoints, RagdollPileEnergyBoundedBodiesStayAndRerunsAreIdentical) {
  const Scene* scene = find_builtin_scene("ragdolls");
  ASSERT_NE(scene, nullptr);
  SceneRun run(*scene, Params(scene->params));
  SceneRun again(*scene, Params(scene->params));
  const double start = kinetic_and_potential(run.world());
  const Aabb box{{-4.6f, -0.2f}, {4.6f, 30.0f}};
  for (std::int64_t step = 0; step < scene->view.steps; ++step) {
    run.step();
    again.step();
    ASSERT_EQ(run.world().state_hash(), again.world().state_hash()) << "step " << step + 1;
    // No energy is made: the pile only loses what it had at the start (a small margin for the
    // soft joints' stored energy).
    ASSERT_LE(kinetic_and_potential(run.world()), start + 0.02 * std::abs(start) + 1.0) << "step " << step + 1;
  }
  for (const BodyId id : run.world().body_ids()) {
    if (run.world().body(id).type != BodyType::Dynamic) continue;
    const vec2 p = run.world().body(id).transform.position;
    EXPECT_TRUE(box.contains(p)) << "body " << id.index << " at " << p.x << ", " << p.y;
  }
  EXPECT_TRUE(run.divergences().empty());
}

TEST(DemoJoints, RopeBridgeSagsAsItsCatenary) {
  const Scene* scene = find_builtin_scene("rope_bridge");
  ASSERT_NE(scene, nullptr);
  Params params(scene->params);
  params.set("crates", 0.0);
  SceneRun run(*scene, params);
  for (int i = 0; i < 900; ++i) run.step();
  // The lowest plank centre against the catenary y = c cosh(x / c) of half-span a and length L:
  // L = 2 c sinh(a / c); sag = c (cosh(a / c) - 1).
  const double a = 7.0, length = 14.0 * (1.0 + params.number("slack"));
  double low = 0.01, high = 1000.0;
  for (int i = 0; i < 200; ++i) {
    const double c = 0.5 * (low + high);
    if (2.0 * c * std::sinh(a / c) > length) low = c; else high = c;
  }
  const double c = 0.5 * (low + high);
  const double sag = c * (std::cosh(a / c) - 1.0);
  float lowest = 1e9f;
  for (const BodyId id : run.world().body_ids()) {
    const BodyView body = run.world().body(id);
    if (body.type == BodyType::Dynamic) lowest = std::min(lowest, body.transform.position.y);
  }
  const double measured = 5.0 - lowest;
  EXPECT_NEAR(measured, sag, 0.05 * sag) << "catenary sag " << sag << " m, bridge " << measured << " m";
}

TEST(DemoJoints, SceneFileJointsUseWorldAnchorsAndEvents) {
  const std::string text = R"({
    "bodies": [
      {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [10, 0.5]}, "position": [0, -0.5]},
      {"name": "arm", "shape": {"type": "oriented_box", "half_extents": [1, 0.1]}, "position": [1, 5]},
      {"name": "crate", "shape": {"type": "oriented_box", "half_extents": [0.4, 0.4]}, "position": [-3, 1]}
    ],
    "joints": [
      {"type": "revolute", "name": "hinge", "bodies": ["ground", "arm"], "anchor": [0, 5]},
      {"type": "mouse", "name": "drag", "body": "crate", "target": [-3, 3], "hertz": 5, "damping_ratio": 0.7, "max_force": 1000}
    ],
    "events": [
      {"step": 30, "type": "mouse_target", "joint": "drag", "target": [-1, 3]},
      {"step": 90, "type": "destroy_joint", "joint": "hinge"}
    ],
    "run": {"steps": 120}
  })";
  const Scene scene = parse_scene(text, "joints.json");
  ASSERT_EQ(scene.joints.size(), 2u);
  SceneRun run(scene, Params(scene.params));
  EXPECT_EQ(run.world().joint_count(), 2);
  for (int i = 0; i < 90; ++i) run.step();  // steps 0..89: the destroy applies before step 90
  // The hinge holds the arm's left end at the world anchor (0, 5).
  const BodyView arm = run.world().body(run.world().body_ids()[1]);
  const vec2 end = arm.transform.apply(vec2(-1.0f, 0.0f));
  EXPECT_NEAR(end.x, 0.0f, 0.02f);
  EXPECT_NEAR(end.y, 5.0f, 0.02f);
  // The crate followed the moved target.
  const BodyView crate = run.world().body(run.world().body_ids()[2]);
  EXPECT_NEAR(crate.transform.position.x, -1.0f, 0.1f);
  run.step();
  EXPECT_FALSE(run.joint_named("hinge").has_value());
  EXPECT_TRUE(run.joint_named("drag").has_value());
  EXPECT_EQ(run.world().joint_count(), 1);
}

TEST(DemoJoints, SceneFileJointErrorsNameThePath) {
  const auto message = [](const std::string& joints) {
    const std::string text = R"({"bodies": [
      {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [10, 0.5]}, "position": [0, -0.5]},
      {"name": "arm", "shape": {"type": "oriented_box", "half_extents": [1, 0.1]}, "position": [1, 5]}],
      "joints": )" + joints + "}";
    try {
      parse_scene(text, "scene.json");
    } catch (const UsageError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"([{"type": "weld", "bodies": ["ground", "arm"], "anchor": [0, 5]},
                        {"type": "weld", "bodies": ["ground", "arm"], "anchor": [0, 5]},
                        {"type": "weld", "bodies": ["ground", "armm"], "anchor": [0, 5]}])"),
            "scene.json: joints[2].bodies[1]: unknown body \"armm\"");
  EXPECT_NE(message(R"([{"type": "revolute", "bodies": ["arm", "arm"], "anchor": [0, 5]}])").find("joints[0].bodies[1]"),
            std::string::npos);
  EXPECT_NE(message(R"([{"type": "revolute", "bodies": ["ground", "arm"], "anchor": [0, 5], "limits": [1, -1]}])")
                .find("joints[0].limits: the limits are reversed"),
            std::string::npos);
}

// The scene files' `force` event (a force, and torque, applied before each of `steps`
// consecutive steps), and impulse and force events on bodies they cannot move (static,
// kinematic): rejected naming the file, the event and the reason, at load time when the
// body's type is known there, else when the event applies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/world.h"
#include "scene_load_error.h"
#include "scene/scene_run.h"
#include "scene/scene_loader.h"
#include "scene/usage_error.h"

using namespace impulse2d;
using namespace impulse2d::demos;
using impulse2d::demos::test::load_error;

namespace {

/// A 1 m radius disc of density 1 (mass pi kg) at rest in space (no gravity), with `events`
/// (JSON array text) and `settings` (JSON object text).
std::string disc_scene(const std::string& events, const std::string& settings = "{}") {
  return R"({"settings": )" + settings + R"(,
    "bodies": [
      {"name": "wall", "type": "static", "shape": {"type": "box", "half_extents": [1, 1]},
       "position": [-50, 0], "material": "Static"},
      {"name": "disc", "shape": {"type": "circle", "radius": 1}, "position": [0, 0],
       "material": {"density": 1, "restitution": 0, "static_friction": 0, "dynamic_friction": 0}}
    ],
    "events": )" + events + "}";
}

const std::string no_gravity = R"({"gravity": [0, 0]})";

}  // namespace

TEST(ForceEvent, LoadsWithEveryField) {
  const Scene scene = parse_scene(
      disc_scene(R"([{"step": 3, "type": "force", "body": "disc", "force": [2, -1],
                      "point": [0, 0.5], "torque": 0.25, "steps": 7}])"),
      "force.json");
  ASSERT_EQ(scene.events.size(), 1u);
  const SceneEvent& event = scene.events[0];
  EXPECT_EQ(event.kind, SceneEventKind::Force);
  EXPECT_EQ(event.step, 3);
  EXPECT_EQ(event.body, 1);
  EXPECT_FLOAT_EQ(event.force.x, 2.0f);
  EXPECT_FLOAT_EQ(event.force.y, -1.0f);
  ASSERT_TRUE(event.point.has_value());
  EXPECT_FLOAT_EQ(event.point->y, 0.5f);
  EXPECT_FLOAT_EQ(event.torque, 0.25f);
  EXPECT_EQ(event.steps, 7);
  EXPECT_EQ(event.origin, "events[0]");
}

// A force F on a free body of mass m from step N for K steps: semi-implicit Euler adds F/m h
// in each of its sub-steps, so after step s the speed is F/m dt * clamp(s - N, 0, K) exactly
// up to float rounding of the sums (K <= 10 additions of ~1e-2: 1e-6 covers them). The same
// with the soft step's 4 sub-steps (the force is integrated in every one of them).
TEST(ForceEvent, AppliesForExactlyItsSteps) {
  for (const std::string& settings :
       {std::string(no_gravity),
        std::string(R"({"gravity": [0, 0], "solver": "soft_step", "substeps": 4})")}) {
    const Scene scene = parse_scene(
        disc_scene(R"([{"step": 5, "type": "force", "body": "disc", "force": [2, 0], "steps": 10}])",
                   settings),
        "force.json");
    SceneRun run(scene, Params(scene.params));
    const BodyId disc = run.world().body_ids()[1];
    const float mass = run.world().body(disc).mass;
    const float dt = run.world().settings().time_step;
    for (int s = 1; s <= 30; ++s) {
      run.step();
      const int pushed = std::min(std::max(s - 5, 0), 10);
      EXPECT_NEAR(run.world().body(disc).linear_velocity.x, 2.0f / mass * dt * pushed, 1e-6f)
          << "after step " << s << " with settings " << settings;
      EXPECT_EQ(run.world().body(disc).angular_velocity, 0.0f);
    }
  }
}

// The point (world, where the force acts at its first step) gives the torque r x F, and the
// torque field adds to it: one step of each changes w by (r x F + T) / I dt.
TEST(ForceEvent, PointAndTorqueTurnTheBody) {
  const Scene scene = parse_scene(
      disc_scene(R"([{"step": 0, "type": "force", "body": "disc", "force": [2, 0],
                      "point": [0, 0.5], "torque": 0.25, "steps": 1}])",
                 no_gravity),
      "force.json");
  SceneRun run(scene, Params(scene.params));
  const BodyId disc = run.world().body_ids()[1];
  run.step();
  const float dt = run.world().settings().time_step;
  const float torque = cross(vec2(0.0f, 0.5f), vec2(2.0f, 0.0f)) + 0.25f;  // -1 + 0.25
  const BodyView after_one = run.world().body(disc);
  EXPECT_NEAR(after_one.angular_velocity, torque / after_one.inertia * dt, 1e-6f);
  run.step();  // one step only
  const BodyView after_two = run.world().body(disc);
  EXPECT_NEAR(after_two.angular_velocity, torque / after_two.inertia * dt, 1e-6f);
}

TEST(ForceEvent, BadFieldsAreRejectedWithTheirPath) {
  const auto force_event = [](const std::string& fields) {
    return disc_scene(R"([{"step": 0, "type": "force", "body": "disc", )" + fields + "}]",
                      no_gravity);
  };
  std::string message = load_error(force_event(R"("force": [1, 0], "steps": 0)"));
  EXPECT_NE(message.find("bad.json: events[0].steps"), std::string::npos) << message;
  message = load_error(force_event(R"("force": [1, 0], "steps": 2.5)"));
  EXPECT_NE(message.find("events[0].steps"), std::string::npos) << message;
  message = load_error(force_event(R"("force": [1, 0])"));
  EXPECT_NE(message.find("steps"), std::string::npos) << message;
  message = load_error(force_event(R"("force": [1e30, 0], "steps": 2)"));
  EXPECT_NE(message.find("events[0].force[0]"), std::string::npos) << message;
  message = load_error(force_event(R"("force": [1, 0], "steps": 2, "impulse": [1, 0])"));
  EXPECT_NE(message.find("impulse"), std::string::npos) << message;
  message = load_error(force_event(R"("force": [1, 0], "steps": 2, "torque": 1e30)"));
  EXPECT_NE(message.find("events[0].torque"), std::string::npos) << message;
}

TEST(UnmovableBody, ImpulseOrForceOnAStaticOrKinematicBodyIsRejectedAtLoad) {
  std::string message = load_error(
      disc_scene(R"([{"step": 0, "type": "impulse", "body": "wall", "impulse": [1, 0]}])"));
  EXPECT_NE(message.find(R"(bad.json: events[0].body: body 0 ("wall") is static: an impulse cannot move it)"),
            std::string::npos)
      << message;
  message = load_error(disc_scene(
      R"([{"step": 0, "type": "remove", "body": 1},
          {"step": 4, "type": "force", "body": 0, "force": [1, 0], "steps": 3}])"));
  EXPECT_NE(message.find(R"(events[1].body: body 0 ("wall") is static: a force cannot move it)"),
            std::string::npos)
      << message;
  // A spawned body's type is known at load too.
  message = load_error(disc_scene(
      R"([{"step": 2, "type": "spawn", "body": {"name": "lift", "type": "kinematic",
            "shape": {"type": "box", "half_extents": [1, 0.2]}, "position": [5, 0]}},
          {"step": 3, "type": "impulse", "body": "lift", "impulse": [0, 1]}])"));
  EXPECT_NE(message.find(R"(events[1].body: body 2 ("lift") is kinematic: an impulse cannot move it)"),
            std::string::npos)
      << message;
}

namespace {

/// A built-in-like scene (C++ builder): body 0 static, body 1 dynamic.
Scene built_scene(std::vector<SceneEvent> events) {
  Scene scene;
  scene.name = "built";
  scene.source = "built.json";
  scene.model.boxes = true;
  scene.build = [](World& world, const Params&) {
    BodyDef ground;
    ground.type = BodyType::Static;
    world.create_body(ground, make_box({5.0f, 0.5f}));
    BodyDef box;
    box.position = {0.0f, 2.0f};
    world.create_body(box, make_box({0.5f, 0.5f}));
  };
  scene.events = std::move(events);
  for (std::size_t i = 0; i < scene.events.size(); ++i) {
    scene.events[i].origin = "events[" + std::to_string(i) + "]";
  }
  return scene;
}

std::string run_error(const Scene& scene, int steps) {
  try {
    SceneRun run(scene, Params(scene.params));
    for (int i = 0; i < steps; ++i) run.step();
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

// A builder's bodies are only known once built: the run rejects the event before stepping,
// and a body spawned by a C++ scene's event when the event applies.
TEST(UnmovableBody, BuilderBodiesAreCheckedByTheRun) {
  SceneEvent force;
  force.kind = SceneEventKind::Force;
  force.step = 3;
  force.body = 0;
  force.force = {1.0f, 0.0f};
  force.steps = 2;
  EXPECT_EQ(run_error(built_scene({force}), 0),
            "built.json: events[0]: body 0 is static: a force cannot move it");
  force.body = 1;  // the dynamic box: accepted
  EXPECT_EQ(run_error(built_scene({force}), 10), "");

  SceneEvent spawn;
  spawn.kind = SceneEventKind::Spawn;
  spawn.step = 1;
  spawn.spawn.def.type = BodyType::Kinematic;
  spawn.spawn.shape = make_box({1.0f, 0.2f});
  SceneEvent impulse;
  impulse.kind = SceneEventKind::Impulse;
  impulse.step = 2;
  impulse.body = 2;
  impulse.impulse = {0.0f, 1.0f};
  const Scene scene = built_scene({spawn, impulse});
  EXPECT_EQ(run_error(scene, 2), "");  // not applied yet
  EXPECT_EQ(run_error(scene, 3),
            "built.json: events[1]: body 2 is kinematic: an impulse cannot move it (a kinematic "
            "body moves only at its set velocity)");
}

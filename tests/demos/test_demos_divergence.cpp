// A body whose state becomes non-finite is reported by the run (step, creation index, name)
// and, with strict on, stops the run with a message naming it.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "core/world.h"
#include "scene/scene.h"
#include "scene/scene_run.h"

namespace impulse2d::demos {
namespace {

/// One ball under a gravity that overflows its velocity to infinity within a few steps.
Scene exploding_scene() {
  Scene scene;
  scene.name = "exploding";
  scene.source = "exploding.json";
  scene.settings.gravity = {0.0f, -3e38f};
  scene.settings.max_linear_speed = std::numeric_limits<float>::max();
  scene.model.circles = true;
  scene.body_names[0] = "ball";
  scene.build = [](World& world, const Params&) {
    BodyDef ball;
    ball.position = {0.0f, 0.0f};
    world.create_body(ball, make_circle(0.5f));
  };
  return scene;
}

TEST(Divergence, IsRecordedWithStepBodyAndName) {
  const Scene scene = exploding_scene();
  SceneRun run(scene, Params{});
  for (int i = 0; i < 200; ++i) run.step();
  ASSERT_FALSE(run.divergences().empty());
  const Divergence& first = run.divergences().front();
  EXPECT_EQ(first.body, 0);
  EXPECT_EQ(first.name, "ball");
  EXPECT_GT(first.step, 0);
  const std::string text = describe_divergence(scene, first);
  EXPECT_NE(text.find("exploding.json: body 0 (\"ball\")"), std::string::npos) << text;
}

TEST(Divergence, StrictStopsTheRunAtTheFirst) {
  const Scene scene = exploding_scene();
  SceneRun run(scene, Params{});
  run.set_strict(true);
  try {
    for (int i = 0; i < 200; ++i) run.step();
    FAIL() << "no divergence reported";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("--strict"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace impulse2d::demos

// Built-in scenes: each builds under its declared model, steps without diverging and renders;
// the registry, parameters, frame plans and the deterministic random source.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/world.h"
#include "frames/frame_plan.h"
#include "scene/params.h"
#include "frames/scene_camera.h"
#include "demos/scene_random.h"
#include "demos/scene_registry.h"
#include "scene/scene_run.h"
#include "scene/usage_error.h"
#include "render/frame_renderer.h"

using namespace impulse2d;
using namespace impulse2d::demos;

namespace {

/// Smaller parameters where a scene's defaults are large, so the suite stays fast.
Params small_params(const Scene& scene) {
  Params params(scene.params);
  if (scene.name == "ball_pit") params.set("balls", 1000.0);  // still 1000+: the point of it
  if (scene.name == "pyramid") params.set("rows", 20.0);
  return params;
}

bool all_finite(const World& world) {
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    if (!is_finite(body.transform.position) || !is_finite(body.linear_velocity) ||
        !std::isfinite(body.angle) || !std::isfinite(body.angular_velocity)) {
      return false;
    }
  }
  return true;
}

}  // namespace

TEST(Registry, ListsTheRequiredScenesOnceEach) {
  std::set<std::string> names;
  for (const Scene& scene : builtin_scenes()) {
    EXPECT_TRUE(names.insert(scene.name).second) << scene.name;
    EXPECT_FALSE(scene.description.empty()) << scene.name;
    EXPECT_TRUE(scene.build) << scene.name;
  }
  for (const char* required :
       {"tutorial", "materials", "friction_ramp", "shape_pairs", "pyramid", "stack",
        "newtons_cradle", "bullet", "ball_pit", "random_polygons", "push"}) {
    EXPECT_EQ(names.count(required), 1u) << required;
  }
  EXPECT_EQ(default_scene().name, "tutorial");
  EXPECT_THROW(resolve_scene("no_such_scene"), UsageError);
}

class BuiltinScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinScene, BuildsUnderItsModelStepsAndRenders) {
  const Scene& scene = *find_builtin_scene(GetParam());
  SceneRun run(scene, small_params(scene));
  const WorldSettings& settings = run.world().settings();
  EXPECT_EQ(settings.enable_rotation, scene.model.rotation);
  EXPECT_EQ(settings.enable_friction, scene.model.friction);
  EXPECT_EQ(settings.enable_restitution, scene.model.restitution);
  EXPECT_EQ(settings.enable_continuous, scene.model.ccd);
  EXPECT_EQ(settings.enable_sleeping, scene.model.sleeping);
  EXPECT_EQ(settings.velocity_iterations, scene.model.velocity_iterations);
  EXPECT_GT(run.world().body_count(), 0);

  const std::int64_t steps = std::min<std::int64_t>(scene.view.steps, 120);
  for (std::int64_t i = 0; i < steps; ++i) {
    run.step();
    ASSERT_TRUE(run.world().diverged_bodies().empty()) << "step " << i;
  }
  EXPECT_TRUE(all_finite(run.world()));

  render::FrameRenderer renderer(160, 120);
  const render::Camera camera = scene_camera(scene.view.camera, run.world(), 160, 120);
  render::FrameOptions options;
  options.draw = scene.view.draw;
  render::HudInfo hud;
  hud.scene_name = scene.name;
  hud.step = steps;
  const render::Frame frame = renderer.render(run.world(), camera, options, hud);
  ASSERT_EQ(frame.width, 160);
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
    colours.insert(static_cast<std::uint32_t>(frame.rgba[i]) << 16 | frame.rgba[i + 1] << 8 |
                   frame.rgba[i + 2]);
  }
  EXPECT_GT(colours.size(), 3u) << "the frame looks empty";
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinScene, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const Scene& scene : builtin_scenes()) names.push_back(scene.name);
                           return names;
                         }()),
                         [](const auto& test) { return test.param; });

TEST(BuiltinScenes, ScriptedRainIsDeterministic) {
  const Scene& scene = *find_builtin_scene("tutorial");
  SceneRun first(scene, Params(scene.params)), second(scene, Params(scene.params));
  for (int i = 0; i < 200; ++i) {
    first.step();
    second.step();
  }
  EXPECT_GT(first.world().body_count(), 4);
  EXPECT_EQ(first.world().state_hash(), second.world().state_hash());
}

TEST(BuiltinScenes, PushHoldsBelowMuSWeightAndSlidesAtTheDynamicAccelerationAbove) {
  const Scene& scene = *find_builtin_scene("push");
  SceneRun run(scene, Params(scene.params));
  std::vector<BodyId> boxes;
  for (const BodyId id : run.world().body_ids()) {
    if (run.world().body(id).type == BodyType::Dynamic) boxes.push_back(id);
  }
  ASSERT_EQ(boxes.size(), 3u);
  const float start = run.world().body(boxes[0]).transform.position.x;
  for (int i = 0; i < 60; ++i) run.step();
  std::vector<float> speed_at_1s;
  for (const BodyId id : boxes) speed_at_1s.push_back(run.world().body(id).linear_velocity.x);
  for (int i = 0; i < 60; ++i) run.step();
  // 0.95 mu_s W: holds (under 1 mm in 2 s).
  EXPECT_LT(std::fabs(run.world().body(boxes[0]).transform.position.x - start), 1e-3f);
  // 1.05 and 2 mu_s W: a = g (ratio mu_s - mu_d) within 1 %, measured over the second second.
  const float g = -run.world().settings().gravity.y;
  const float ratios[2] = {1.05f, 2.0f};
  for (int lane = 1; lane <= 2; ++lane) {
    const float expected = g * (ratios[lane - 1] * 0.5f - 0.3f);
    const float measured = run.world().body(boxes[lane]).linear_velocity.x - speed_at_1s[lane];
    EXPECT_NEAR(measured, expected, 0.01f * expected) << "lane " << lane;
  }
}

TEST(BuiltinScenes, FrictionRampHoldsAboveTanThetaAndSlidesBelow) {
  const Scene& scene = *find_builtin_scene("friction_ramp");
  SceneRun run(scene, Params(scene.params));
  std::vector<vec2> start;
  std::vector<BodyId> blocks;
  for (const BodyId id : run.world().body_ids()) {
    if (run.world().body(id).type == BodyType::Dynamic) blocks.push_back(id);
  }
  ASSERT_EQ(blocks.size(), 4u);
  for (const BodyId id : blocks) start.push_back(run.world().body(id).transform.position);
  for (int i = 0; i < 120; ++i) run.step();
  std::vector<float> travelled;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    travelled.push_back(glm::length(run.world().body(blocks[i]).transform.position - start[i]));
  }
  EXPECT_LT(travelled[0], 0.02f);  // mu_s above tan(theta): holds
  EXPECT_GT(travelled[1], 0.2f);   // below: slides, slower for larger mu_d
  EXPECT_GT(travelled[2], travelled[1]);
  EXPECT_GT(travelled[3], travelled[2]);
}

TEST(BuiltinScenes, BulletTunnelsWithoutCcdAndIsStoppedWithIt) {
  const Scene& scene = *find_builtin_scene("bullet");
  SceneRun run(scene, Params(scene.params));
  for (int i = 0; i < 10; ++i) run.step();
  const std::vector<BodyId> ids = run.world().body_ids();  // wall, slow, fast, fast + CCD
  ASSERT_EQ(ids.size(), 4u);
  EXPECT_GT(run.world().body(ids[2]).transform.position.x, 0.0f);
  EXPECT_LT(run.world().body(ids[3]).transform.position.x, 0.0f);
}

TEST(SceneModel, ABodyOfAnUndeclaredKindIsRejected) {
  Scene scene;
  scene.name = "circles_only";
  scene.model.circles = true;
  scene.build = [](World& world, const Params&) {
    world.create_body(BodyDef{}, make_circle(0.5f));
    world.create_body(BodyDef{}, make_box({0.5f, 0.5f}));
  };
  try {
    SceneRun run(scene, Params{});
    FAIL() << "expected UsageError";
  } catch (const UsageError& error) {
    EXPECT_NE(std::string(error.what()).find("body 1 is a box"), std::string::npos) << error.what();
  }
}

TEST(Params, ChecksNamesNumbersWholenessAndRanges) {
  Params params({{"rows", "rows", 20, 1, 60, true}, {"angle", "deg", 30, 5, 60, false}});
  EXPECT_EQ(params.integer("rows"), 20);
  params.set_assignment("rows=7");
  EXPECT_EQ(params.integer("rows"), 7);
  params.set_assignment("angle=12.5");
  EXPECT_EQ(params.number("angle"), 12.5);
  EXPECT_THROW(params.set_assignment("cols=3"), UsageError);
  EXPECT_THROW(params.set_assignment("rows=2.5"), UsageError);
  EXPECT_THROW(params.set_assignment("rows=61"), UsageError);
  EXPECT_THROW(params.set_assignment("rows=abc"), UsageError);
  EXPECT_THROW(params.set_assignment("rows=nan"), UsageError);
  EXPECT_THROW(params.set_assignment("rows"), UsageError);
  EXPECT_EQ(params.summary(), "rows=7 angle=12.5");
}

TEST(FramePlan, KeepsStepsInsideTheRunAndRejectsRangesOutsideIt) {
  const FramePlan plan = plan_frames("0:10:5,20", 30);
  EXPECT_EQ(plan.frames, (std::vector<std::int64_t>{0, 5, 10, 20}));
  EXPECT_EQ(plan.steps, 20);
  EXPECT_EQ(plan_frames("::10", 25).frames, (std::vector<std::int64_t>{0, 10, 20}));
  EXPECT_THROW(plan_frames("0:100", 30), UsageError);
  EXPECT_THROW(plan_frames("40:", 30), UsageError);
  EXPECT_THROW(plan_frames("5:1", 30), UsageError);
  EXPECT_EQ(spread_frames(3, 10).frames, (std::vector<std::int64_t>{0, 5, 10}));
}

TEST(SceneRandom, IsTheStandardMersenneTwisterWithExplicitConversions) {
  // std::mt19937's 10000th output for the default seed is fixed by the C++ standard.
  std::mt19937 reference;
  reference.discard(9999);
  EXPECT_EQ(reference(), 4123659995u);
  SceneRandom a(42), b(42);
  for (int i = 0; i < 1000; ++i) {
    const float u = a.unit();
    EXPECT_GE(u, 0.0f);
    EXPECT_LT(u, 1.0f);
    EXPECT_EQ(u, b.unit());
    const int k = a.integer(3, 8);
    EXPECT_GE(k, 3);
    EXPECT_LE(k, 8);
    EXPECT_EQ(k, b.integer(3, 8));
  }
  // The first draw of seed 1 is 1791095845; its top 24 bits scaled by 2^-24 give unit().
  SceneRandom seeded(1);
  EXPECT_EQ(seeded.unit(), std::ldexp(static_cast<float>(1791095845u >> 8), -24));
}

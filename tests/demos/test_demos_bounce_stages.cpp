// The soft step's bounce and shock stages skip work that would change no bit (see
// tests/core/test_bounce_stages.cpp), checked on the built-in scenes that bounce and pile
// bodies of different masses: each is stepped twice, once as it runs by default and once with
// those stages skipping nothing (`WorldState::full_bounce_stages`); the state hashes must be
// equal after every step.
#include "core/solver/world_state.h"
#include "core/world.h"
#include "demos/scene_registry.h"
#include "scene/scene_model.h"

#include <gtest/gtest.h>

#include <string>

namespace impulse2d::demos {
namespace {

class BounceStagesScene : public ::testing::TestWithParam<std::string> {};

TEST_P(BounceStagesScene, SkipsGiveTheBitsOfTheFullStages) {
  const Scene* scene = find_builtin_scene(GetParam());
  ASSERT_NE(scene, nullptr);
  WorldSettings settings = scene->settings;
  apply_model(scene->model, settings);
  World skipping(settings);
  World full(settings);
  WorldState::of(full).full_bounce_stages = true;
  const Params params(scene->params);
  scene->build(skipping, params);
  scene->build(full, params);
  for (int step = 0; step < 300; ++step) {
    skipping.step();
    full.step();
    ASSERT_EQ(skipping.state_hash(), full.state_hash()) << GetParam() << ", step " << step + 1;
  }
}

INSTANTIATE_TEST_SUITE_P(Demos, BounceStagesScene,
                         ::testing::Values("ball_pit", "random_polygons", "tutorial",
                                           "newtons_cradle", "heavy_on_light", "capsules"));

}  // namespace
}  // namespace impulse2d::demos

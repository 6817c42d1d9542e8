// A headless program (a game server) loads a level file with impulse2d::scene and steps it:
// this test binary links the scene library alone, and checks that no GL library came with it.
#include "core/world.h"
#include "scene/scene_loader.h"
#include "scene/scene_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace impulse2d;
using namespace impulse2d::demos;

TEST(SceneHeadless, LoadsAndStepsTheProjectileFileWithoutGl) {
  Scene scene = load_scene_file(std::string(IMPULSE2D_SCENES_DIR) + "/projectile.json");
  apply_model(scene.model, scene.settings);
  World world(scene.settings);
  scene.build(world, Params(scene.params));
  ASSERT_EQ(world.body_count(), 1);
  const BodyId ball = world.body_ids().front();
  const float y0 = world.body(ball).transform.position.y;
  const float vy0 = world.body(ball).linear_velocity.y;
  const int steps = 60;
  for (int i = 0; i < steps; ++i) world.step();
  // Semi-implicit Euler at the sub-step h: y = y0 + vy0 t - g t^2 / 2 - g t h / 2.
  const float dt = scene.settings.time_step;
  const float h = dt / static_cast<float>(scene.settings.substeps);
  const float t = dt * steps;
  const float g = -scene.settings.gravity.y;
  const float expected = y0 + vy0 * t - 0.5f * g * t * t - 0.5f * g * t * h;
  EXPECT_NEAR(world.body(ball).transform.position.y, expected, 1e-3f);

  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    for (const char* gl : {"libOSMesa", "libEGL", "libGL", "libOpenGL"}) {
      EXPECT_EQ(line.find(gl), std::string::npos) << "the scene library pulled in " << line;
    }
  }
}

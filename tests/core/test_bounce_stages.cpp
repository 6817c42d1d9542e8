// The soft step's bounce and shock stages skip work that would change no bit (soft_step_solver.cpp:
// a sub-step without a bounce neither applies them nor writes the states out and reads them back;
// a support order whose contacts support as before is kept). Each test steps a world twice, once
// as it runs by default and once with those stages skipping nothing
// (`WorldState::full_bounce_stages`): the state hashes must be equal after every step, through
// impacts, bounces beside resting contacts (the waiting rule), heavy bodies on light ones (the
// shock pass), sleeping and workers.
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <functional>

using namespace impulse2d;

namespace {

// A pour of elastic balls of mixed sizes (masses up to 2.25:1, past the shock pass's 1.44 at
// one iteration a sub-step) and a few boxes into a bin, as the ball pit demo pours them: the
// landings go on for seconds beside balls already at rest (bounces, waits, the shock pass).
void pour(World& world) {
  constexpr float half_width = 3.0f;
  constexpr float spacing = 0.62f;
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.position = {0.0f, -0.5f};
  world.create_body(wall, make_box({half_width + 1.0f, 0.5f}));
  for (float side : {-1.0f, 1.0f}) {
    wall.position = {side * (half_width + 0.5f), 6.0f};
    world.create_body(wall, make_box({0.5f, 6.0f}));
  }
  const int per_row = static_cast<int>(2.0f * half_width / spacing) - 1;
  for (int i = 0; i < 160; ++i) {
    const int row = i / per_row;
    const int column = i % per_row;
    BodyDef body;
    body.position = {-half_width + spacing * (static_cast<float>(column) + 1.0f) +
                         0.03f * static_cast<float>((i * 7) % 5 - 2),
                     0.5f + spacing * static_cast<float>(row)};
    body.material.density = 0.4f;
    body.material.restitution = 0.3f;
    const float size = 0.2f + 0.025f * static_cast<float>((i * 3) % 5);  // 0.2 to 0.3 m
    if (i % 11 == 5) {
      world.create_body(body, make_box({size, size}));
    } else {
      world.create_body(body, make_circle(size));
    }
  }
}

// Five touching elastic balls on a floor, the first struck: the impact travels along the row
// one contact per step, the others waiting (Newton's cradle).
void cradle(World& world) {
  BodyDef floor;
  floor.type = BodyType::Static;
  floor.position = {0.0f, -0.5f};
  floor.material.restitution = 1.0f;
  world.create_body(floor, make_box({20.0f, 0.5f}));
  for (int i = 0; i < 5; ++i) {
    BodyDef ball;
    ball.position = {static_cast<float>(i), 0.5f};
    ball.material.restitution = 1.0f;
    ball.material.static_friction = 0.0f;
    ball.material.dynamic_friction = 0.0f;
    world.create_body(ball, make_circle(0.5f));
  }
  BodyDef striker;
  striker.position = {-3.0f, 0.5f};
  striker.linear_velocity = {6.0f, 0.0f};
  striker.material.restitution = 1.0f;
  striker.material.static_friction = 0.0f;
  striker.material.dynamic_friction = 0.0f;
  world.create_body(striker, make_circle(0.5f));
}

// Steps `build`'s world by default and with the stages skipping nothing, `steps` times; the
// state hashes must agree after every step.
void compare_with_full_twin(const WorldSettings& settings, const std::function<void(World&)>& build,
                            int steps) {
  World skipping(settings);
  World full(settings);
  WorldState::of(full).full_bounce_stages = true;
  build(skipping);
  build(full);
  for (int step = 0; step < steps; ++step) {
    skipping.step();
    full.step();
    ASSERT_EQ(skipping.state_hash(), full.state_hash()) << "step " << step + 1;
  }
}

}  // namespace

TEST(BounceStages, SkipsGiveTheBitsOfTheFullStagesInAPour) {
  compare_with_full_twin(WorldSettings{}, pour, 400);
}

TEST(BounceStages, SkipsGiveTheBitsOfTheFullStagesInNewtonsCradle) {
  compare_with_full_twin(WorldSettings{}, cradle, 200);
}

TEST(BounceStages, WithSleepingBodies) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  compare_with_full_twin(settings, pour, 400);
}

TEST(BounceStages, WithWorkers) {
  WorldSettings settings;
  settings.worker_count = 2;
  compare_with_full_twin(settings, pour, 300);
}

// The comparisons above are not vacuous: the pour has steps with bounces and steps
// without (a point that bounced keeps `bounced` until the next step), and contacts of a heavy
// body on a light one (the shock pass).
TEST(BounceStages, ThePourBouncesAndCallsTheShockPass) {
  World world;
  pour(world);
  int steps_with_bounces = 0;
  int steps_without = 0;
  bool heavy_on_light = false;
  for (int step = 0; step < 400; ++step) {
    world.step();
    bool bounced = false;
    for (const Contact& contact : world.contacts()) {
      for (int i = 0; i < contact.point_count; ++i) bounced = bounced || contact.points[i].bounced;
    }
    (bounced ? steps_with_bounces : steps_without) += 1;
    heavy_on_light = heavy_on_light || WorldState::of(world).wide_contacts.has_heavy_on_light();
  }
  EXPECT_GT(steps_with_bounces, 10);
  EXPECT_GT(steps_without, 10);
  EXPECT_TRUE(heavy_on_light);
}

// Bounce apex heights h_k = e^(2k) h0 (restitution threshold off), with the error bound
// derived in bounce_apexes.h, and the resting threshold.
#include "bounce_apexes.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace impulse2d;

using namespace impulse2d::bounce_test;

class Bounce : public ::testing::TestWithParam<float> {};

TEST_P(Bounce, ApexHeightsFollowESquaredPowers) {
  const float e = GetParam();
  const double h0 = 2.0, g = 9.81;
  const float dt = 1.0f / 240.0f;
  const int bounces = 4;
  WorldSettings settings;
  settings.time_step = dt;
  const std::vector<double> apexes = bounce_apexes(settings, e, static_cast<float>(h0), bounces);
  ASSERT_EQ(apexes.size(), static_cast<std::size_t>(bounces));
  for (int k = 1; k <= bounces; ++k) {
    EXPECT_NEAR(apexes[static_cast<std::size_t>(k - 1)], std::pow(e, 2 * k) * h0,
                bounce_apex_tolerance(e, h0, g, dt, k))
        << "bounce " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Restitution, Bounce, ::testing::Values(0.5f, 0.8f, 0.95f));

TEST(Bounce, RestitutionThresholdLetsASlowBallSettle) {
  WorldSettings settings;  // default threshold 1 m/s
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -1};
  world.create_body(ground, make_box({5, 1}));
  BodyDef ball;
  ball.material = materials::super_ball();
  ball.position = {0, 0.25f + 0.02f};  // drop 2 cm: impact ~0.6 m/s, below the threshold
  const BodyId id = world.create_body(ball, make_circle(0.25f));
  for (int i = 0; i < 60; ++i) world.step();
  EXPECT_NEAR(world.body(id).linear_velocity.y, 0.0f, 1e-3f);
}

// Bounce apex heights h_k = e^(2k) h0 (restitution threshold off).
//
// Error model per bounce, for impact speed v_i = e^(i-1) sqrt(2 g h0) and step dt:
//  - the contact is found up to one step late, so the reflected speed is off by <= g dt,
//    which moves the apex by <= v_i g dt / g = v_i dt;
//  - the ball can be up to v_i dt inside the ground when it reflects, and position
//    correction removes at most that overlap again: <= 2 v_i dt of height;
//  - an error at bounce i is scaled by e^2 at every later bounce;
//  - the apex is sampled at step times: <= g dt^2 (semi-implicit Euler's bias included).
// So |h_k - e^(2k) h0| <= sum_i e^(2(k-i)) 3 v_i dt + g dt^2.
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace impulse2d;

namespace {

std::vector<double> measure_apexes(float restitution, float drop_height, float dt, int bounces) {
  WorldSettings settings;
  settings.time_step = dt;
  settings.restitution_threshold = 0.0f;
  settings.enable_friction = false;
  World world(settings);
  Material material{"Ball", 1.0f, restitution, 0.0f, 0.0f};
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = Material{"Floor", 0.0f, restitution, 0.0f, 0.0f};
  ground.position = {0.0f, -1.0f};
  world.create_body(ground, make_box({5.0f, 1.0f}));  // top face at y = 0
  const float radius = 0.25f;
  BodyDef ball;
  ball.material = material;
  ball.position = {0.0f, radius + drop_height};
  const BodyId id = world.create_body(ball, make_circle(radius));

  std::vector<double> apexes;
  double highest = -1.0;
  bool rising = false;
  for (int step = 0; step < 200000 && static_cast<int>(apexes.size()) < bounces; ++step) {
    world.step();
    const Body& body = world.body(id);
    const double height = body.transform.position.y - radius;
    if (body.linear_velocity.y > 0.0f) {
      rising = true;
      highest = std::max(highest, height);
    } else if (rising) {
      apexes.push_back(std::max(highest, height));
      rising = false;
      highest = -1.0;
    }
  }
  return apexes;
}

}  // namespace

class Bounce : public ::testing::TestWithParam<float> {};

TEST_P(Bounce, ApexHeightsFollowESquaredPowers) {
  const float e = GetParam();
  const double h0 = 2.0, g = 9.81;
  const float dt = 1.0f / 240.0f;
  const int bounces = 4;
  const std::vector<double> apexes = measure_apexes(e, static_cast<float>(h0), dt, bounces);
  ASSERT_EQ(apexes.size(), static_cast<std::size_t>(bounces));
  for (int k = 1; k <= bounces; ++k) {
    const double expected = std::pow(e, 2 * k) * h0;
    double tolerance = g * dt * dt;
    for (int i = 1; i <= k; ++i) {
      const double impact_speed = std::pow(e, i - 1) * std::sqrt(2 * g * h0);
      tolerance += std::pow(e, 2 * (k - i)) * 3 * impact_speed * dt;
    }
    EXPECT_NEAR(apexes[static_cast<std::size_t>(k - 1)], expected, tolerance) << "bounce " << k;
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

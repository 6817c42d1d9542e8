// The speed clamp keeps a body's direction and limits its speed, even when the squared
// speed overflows a float (it used to set the velocity to 0 then).
#include <gtest/gtest.h>

#include <cmath>

#include "core/solver/integrate.h"

namespace impulse2d {
namespace {

TEST(SpeedClamp, OverflowingSquaredSpeedKeepsTheDirection) {
  const vec2 velocity(3e30f, -4e30f);  // |v|^2 = 2.5e61: infinite as a float
  const vec2 clamped = clamp_speed(velocity, length_squared(velocity), 100.0f);
  EXPECT_NEAR(clamped.x, 60.0f, 1e-3f);
  EXPECT_NEAR(clamped.y, -80.0f, 1e-3f);
}

TEST(SpeedClamp, OrdinarySpeedsAreScaledAsBefore) {
  const vec2 velocity(300.0f, 400.0f);
  const vec2 clamped = clamp_speed(velocity, length_squared(velocity), 100.0f);
  EXPECT_FLOAT_EQ(clamped.x, 60.0f);
  EXPECT_FLOAT_EQ(clamped.y, 80.0f);
}

TEST(SpeedClamp, NonFiniteVelocityIsLeftForTheWorldToReport) {
  const vec2 velocity(INFINITY, 0.0f);
  EXPECT_TRUE(std::isinf(clamp_speed(velocity, INFINITY, 100.0f).x));
}

}  // namespace
}  // namespace impulse2d

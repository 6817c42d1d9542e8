// The engine's own cos/sin (core/trig.h): within one float rounding of the exact value over
// a wide range of angles, exact at 0, the right signs in every quadrant, and pinned bits so
// that a change in the polynomial or the range reduction cannot pass unnoticed.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstring>

#include "core/math.h"
#include "core/trig.h"

namespace impulse2d {
namespace {

/// Distance in units in the last place between two floats of the same sign region.
std::int64_t ulps_apart(float a, float b) {
  std::int32_t ia, ib;
  std::memcpy(&ia, &a, sizeof ia);
  std::memcpy(&ib, &b, sizeof ib);
  if (ia < 0) ia = INT32_MIN - ia;
  if (ib < 0) ib = INT32_MIN - ib;
  return std::llabs(static_cast<std::int64_t>(ia) - ib);
}

TEST(Trig, WithinOneFloatRoundingOfTheExactValue) {
  std::int64_t worst = 0;
  for (int i = -200000; i <= 200000; ++i) {
    const float angle = static_cast<float>(i) * 0.00731f;  // about -1462..1462 rad
    const CosSin values = cos_sin(angle);
    // long double cos/sin of the exact float angle, rounded once to float: the reference.
    const float cosine = static_cast<float>(std::cos(static_cast<long double>(angle)));
    const float sine = static_cast<float>(std::sin(static_cast<long double>(angle)));
    worst = std::max({worst, ulps_apart(values.cosine, cosine), ulps_apart(values.sine, sine)});
  }
  EXPECT_LE(worst, 1);
}

TEST(Trig, ExactAtZeroAndRightSignsInEachQuadrant) {
  EXPECT_EQ(cos_sin(0.0f).cosine, 1.0f);
  EXPECT_EQ(cos_sin(0.0f).sine, 0.0f);
  const float quarter = 0.7853982f;  // pi/4
  for (int k = -8; k <= 8; ++k) {
    const float angle = quarter * static_cast<float>(2 * k + 1);  // odd multiples of pi/4
    const CosSin values = cos_sin(angle);
    EXPECT_NEAR(values.cosine, std::cos(static_cast<double>(angle)), 1e-6) << k;
    EXPECT_NEAR(values.sine, std::sin(static_cast<double>(angle)), 1e-6) << k;
  }
  EXPECT_TRUE(std::isnan(cos_sin(INFINITY).cosine));
}

TEST(Trig, RotationUsesTheEngineFunctionsBitForBit) {
  for (const float angle : {0.1f, -2.5f, 3.14159f, 100.0f, -1234.5f}) {
    const Rotation rotation = Rotation::from_angle(angle);
    EXPECT_EQ(rotation.cosine, cos_sin(angle).cosine) << angle;
    EXPECT_EQ(rotation.sine, cos_sin(angle).sine) << angle;
  }
}

TEST(Trig, PinnedBitsOfAFewAngles) {
  // Computed once by this implementation; identical on every IEEE-754 machine.
  const struct {
    float angle;
    std::uint32_t cosine_bits, sine_bits;
  } pinned[] = {{0.5f, 0x3f60a940u, 0x3ef57744u},      {-1.25f, 0x3ea171efu, 0xbf72f0a8u},
                {3.0f, 0xbf7d7026u, 0x3e1081c3u},      {10.0f, 0xbf56cd64u, 0xbf0b44f8u},
                {-100.75f, 0x3f79e230u, 0xbe5e80b6u},  {1000.125f, 0x3ee8e8afu, 0x3f63fa96u}};
  for (const auto& each : pinned) {
    const CosSin values = cos_sin(each.angle);
    std::uint32_t c, s;
    std::memcpy(&c, &values.cosine, sizeof c);
    std::memcpy(&s, &values.sine, sizeof s);
    EXPECT_EQ(c, each.cosine_bits) << each.angle;
    EXPECT_EQ(s, each.sine_bits) << each.angle;
  }
}

}  // namespace
}  // namespace impulse2d

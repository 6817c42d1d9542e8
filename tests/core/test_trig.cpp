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
#include <vector>

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

TEST(Trig, FourAtOnceGiveTheSameBitsAsOneAtATime) {
  // Angles on both sides of every quadrant boundary, small and large ones, the edge of the
  // vector path (2^30) and beyond it, and non-finite ones (each batch of four holding one
  // outside the vector path goes one lane at a time).
  std::vector<float> angles = {0.0f, -0.0f, 1e-30f, -1e-30f, 1073741760.0f, -1073741760.0f,
                               1073741824.0f, 3e9f, 1e20f, -1e30f, INFINITY, -INFINITY, NAN};
  for (int quadrant = -8; quadrant <= 8; ++quadrant) {
    const float boundary = static_cast<float>(quadrant * 1.5707963267948966);
    angles.push_back(std::nextafter(boundary, -INFINITY));
    angles.push_back(boundary);
    angles.push_back(std::nextafter(boundary, INFINITY));
  }
  std::uint32_t seed = 12345u;
  for (int i = 0; i < 4000; ++i) {
    seed = seed * 1664525u + 1013904223u;
    const float unit = static_cast<float>(seed >> 8) / 16777216.0f;  // [0, 1)
    const float scale = i % 4 == 0 ? 1e6f : (i % 4 == 1 ? 100.0f : (i % 4 == 2 ? 7.0f : 1.0f));
    angles.push_back((2.0f * unit - 1.0f) * scale);
  }
  while (angles.size() % 4 != 0) angles.push_back(0.25f);
  for (std::size_t i = 0; i < angles.size(); i += 4) {
    CosSin four[4];
    cos_sin_4(&angles[i], four);
    for (int lane = 0; lane < 4; ++lane) {
      const CosSin one = cos_sin(angles[i + lane]);
      EXPECT_EQ(std::memcmp(&four[lane].cosine, &one.cosine, sizeof(float)), 0) << angles[i + lane];
      EXPECT_EQ(std::memcmp(&four[lane].sine, &one.sine, sizeof(float)), 0) << angles[i + lane];
    }
  }
}

}  // namespace
}  // namespace impulse2d

// cos_sin_4's paths (core/trig_kernels.h), each against one `cos_sin` call per lane, bit for bit:
// the path this machine's `cos_sin_4` does not take is still checked here, so a CPU with AVX2
// cannot hide a wrong 2-lane path and one without it says the AVX2 part was skipped.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

#include "core/trig.h"
#include "core/trig_kernels.h"

namespace impulse2d {
namespace {

typedef void (*FourAtOnce)(const float*, CosSin*);

float from_bits(std::uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::uint32_t bits_of(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// `value` and the `steps` floats on each side of it.
void push_neighbourhood(std::vector<float>& angles, float value, int steps) {
  angles.push_back(value);
  float below = value, above = value;
  for (int step = 0; step < steps; ++step) {
    below = std::nextafter(below, -INFINITY);
    above = std::nextafter(above, INFINITY);
    angles.push_back(below);
    angles.push_back(above);
  }
}

// Angles where a vector path could part from `cos_sin`: a dense sweep of [-4 pi, 4 pi], the
// floats around multiples of pi/4 (where the reduced angle is largest and the quadrant may round
// either way) for small and large multiples, tiny and subnormal angles, both zeros, the edge of
// the vector range (2^30) and far beyond it, non-finite ones, and random bit patterns (every
// exponent, NaN payloads included).
std::vector<float> hard_angles() {
  std::vector<float> angles;
  const double four_pi = 4.0 * 3.14159265358979323846;
  const int sweep = 1 << 20;
  for (int i = -sweep; i <= sweep; ++i) {
    angles.push_back(static_cast<float>(four_pi * i / sweep));
  }
  const double quarter_pi = 0.78539816339744830962;
  for (long long k = -64; k <= 64; ++k) {
    push_neighbourhood(angles, static_cast<float>(k * quarter_pi), 8);
  }
  for (long long k = 1; k < (1LL << 31); k = k * 3 + 1) {
    push_neighbourhood(angles, static_cast<float>(k * quarter_pi), 4);
    push_neighbourhood(angles, static_cast<float>(-k * quarter_pi), 4);
  }
  for (const float tiny : {0.0f, 1e-30f, 1e-20f, 1e-10f, 1e-8f, 1e-4f, FLT_MIN, FLT_TRUE_MIN,
                           FLT_MIN / 3.0f, FLT_EPSILON}) {
    push_neighbourhood(angles, tiny, 2);
    push_neighbourhood(angles, -tiny, 2);
  }
  angles.push_back(-0.0f);
  for (const float large : {1073741824.0f, 2147483648.0f, 1e9f, 3e9f, 1e15f, 1e20f, 1e30f,
                            FLT_MAX}) {
    push_neighbourhood(angles, large, 6);
    push_neighbourhood(angles, -large, 6);
  }
  for (const float special : {INFINITY, -INFINITY, NAN, -NAN}) angles.push_back(special);
  angles.push_back(from_bits(0x7fa00001u));  // a signalling NaN
  angles.push_back(from_bits(0xffc12345u));  // a negative quiet NaN with a payload
  std::uint32_t seed = 2463534242u;
  for (int i = 0; i < 200000; ++i) {
    seed ^= seed << 13;
    seed ^= seed >> 17;
    seed ^= seed << 5;
    angles.push_back(from_bits(seed));
  }
  return angles;
}

// The number of angles whose cosine or sine from `path` differs in any bit from `cos_sin`'s,
// taking the angles four at a time from each of the four starting offsets (so every angle
// passes through every lane and shares a batch with different neighbours: an out-of-range one
// sends its whole batch one lane at a time). The first few differences go to `report`.
int count_differences(FourAtOnce path, const std::vector<float>& angles, std::ostream& report) {
  int differences = 0;
  for (std::size_t offset = 0; offset < 4; ++offset) {
    for (std::size_t i = offset; i + 4 <= angles.size(); i += 4) {
      CosSin four[4];
      path(&angles[i], four);
      for (std::size_t lane = 0; lane < 4; ++lane) {
        const float angle = angles[i + lane];
        const CosSin one = cos_sin(angle);
        if (std::memcmp(&four[lane].cosine, &one.cosine, sizeof(float)) == 0 &&
            std::memcmp(&four[lane].sine, &one.sine, sizeof(float)) == 0) {
          continue;
        }
        if (++differences <= 10) {
          report << std::hex << "angle bits 0x" << bits_of(angle) << " (" << angle
                 << "), lane " << lane << ": cos 0x" << bits_of(four[lane].cosine) << " vs 0x"
                 << bits_of(one.cosine) << ", sin 0x" << bits_of(four[lane].sine) << " vs 0x"
                 << bits_of(one.sine) << "\n";
        }
      }
    }
  }
  return differences;
}

TEST(TrigKernels, TwoLanePathGivesCosSinBits) {
  std::ostringstream report;
  EXPECT_EQ(count_differences(cos_sin_4_two_lanes, hard_angles(), report), 0) << report.str();
}

TEST(TrigKernels, Avx2PathGivesCosSinBits) {
#if defined(__x86_64__)
  if (!cos_sin_4_avx2_available()) GTEST_SKIP() << "this CPU has no AVX2: path not checked";
  std::ostringstream report;
  EXPECT_EQ(count_differences(cos_sin_4_avx2, hard_angles(), report), 0) << report.str();
#else
  GTEST_SKIP() << "no AVX2 path on this architecture";
#endif
}

TEST(TrigKernels, ChosenPathGivesCosSinBits) {
  std::ostringstream report;
  EXPECT_EQ(count_differences(cos_sin_4, hard_angles(), report), 0) << report.str();
}

}  // namespace
}  // namespace impulse2d

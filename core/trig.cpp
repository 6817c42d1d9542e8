/// @file trig.cpp
#include "core/trig.h"

#include "core/trig_kernel.h"
#include "core/trig_kernels.h"

#include <cmath>
#include <limits>

namespace impulse2d {
namespace {

// `value` rounded to the nearest integer, ties to even: the shifter's sum (trig_kernel.h)
// below 2^51 in magnitude; larger doubles are integers already.
double nearest_integer(double value) {
  if (!(std::fabs(value) < 2251799813685248.0)) return std::nearbyint(value);  // 2^51
  return (value + kShifter) - kShifter;
}

// The quadrant (an integer-valued double) modulo 4, in 0..3: its low two bits in two's
// complement, as std::fmod(quadrant, 4.0) & 3 gives, without fmod's library call where the
// quadrant fits a 64-bit integer.
long long quadrant_mod_4(double quadrant) {
  if (std::fabs(quadrant) < 4611686018427387904.0) {  // 2^62
    return static_cast<long long>(quadrant) & 3;
  }
  return static_cast<long long>(std::fmod(quadrant, 4.0)) & 3;
}

// cos and sin of r + q pi/2 from c = cos r and s = sin r, q in 0..3.
CosSin in_quadrant(double c, double s, long long q) {
  switch (q) {
    case 0:
      return {static_cast<float>(c), static_cast<float>(s)};
    case 1:
      return {static_cast<float>(-s), static_cast<float>(c)};
    case 2:
      return {static_cast<float>(-c), static_cast<float>(-s)};
    default:
      return {static_cast<float>(s), static_cast<float>(-c)};
  }
}

}  // namespace

CosSin cos_sin(float angle) {
  if (!std::isfinite(angle)) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    return {nan, nan};
  }
  const double x = angle;
  const double quadrant = nearest_integer(x * kTwoOverPi);
  const double r = (x - quadrant * kHalfPiHigh) - quadrant * kHalfPiLow;
  const double s = sine_polynomial(r);
  const double c = cosine_polynomial(r);
  return in_quadrant(c, s, quadrant_mod_4(quadrant));
}

void cos_sin_4_two_lanes(const float* angles, CosSin* results) {
  if (all_in_vector_range(angles)) {
    cos_sin_4_lanes<2>(angles, results);
    return;
  }
  for (int lane = 0; lane < 4; ++lane) results[lane] = cos_sin(angles[lane]);
}

#if defined(__x86_64__)
bool cos_sin_4_avx2_available() { return __builtin_cpu_supports("avx2"); }
#endif

void cos_sin_4(const float* angles, CosSin* results) {
#if defined(__x86_64__)
  if (cos_sin_4_avx2_available()) {
    cos_sin_4_avx2(angles, results);
    return;
  }
#endif
  cos_sin_4_two_lanes(angles, results);
}

}  // namespace impulse2d

/// @file trig.cpp
#include "core/trig.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace impulse2d {
namespace {

// pi/2 split in two doubles (Cody-Waite): the first has trailing zero bits so that
// quadrant * kHalfPiHigh is exact for quadrants below 2^20; the second carries the rest.
constexpr double kHalfPiHigh = 1.5707963267341256;
constexpr double kHalfPiLow = 6.077100506506192e-11;
constexpr double kTwoOverPi = 0.6366197723675814;

// Taylor series on |r| <= pi/4, evaluated by Horner's rule; the first omitted term is below
// 2^-56 of the result.
// Written once for a double and for a vector of doubles (the same operations lane by lane).
template <class Real>
Real sine_polynomial(Real r) {
  const Real r2 = r * r;
  Real sum = Real{} + -1.0 / 1307674368000.0;  // -1/15!
  sum = sum * r2 + 1.0 / 6227020800.0;             // 1/13!
  sum = sum * r2 - 1.0 / 39916800.0;               // -1/11!
  sum = sum * r2 + 1.0 / 362880.0;                 // 1/9!
  sum = sum * r2 - 1.0 / 5040.0;                   // -1/7!
  sum = sum * r2 + 1.0 / 120.0;                    // 1/5!
  sum = sum * r2 - 1.0 / 6.0;                      // -1/3!
  return r + r * r2 * sum;
}

template <class Real>
Real cosine_polynomial(Real r) {
  const Real r2 = r * r;
  Real sum = Real{} + 1.0 / 20922789888000.0;  // 1/16!
  sum = sum * r2 - 1.0 / 87178291200.0;            // -1/14!
  sum = sum * r2 + 1.0 / 479001600.0;              // 1/12!
  sum = sum * r2 - 1.0 / 3628800.0;                // -1/10!
  sum = sum * r2 + 1.0 / 40320.0;                  // 1/8!
  sum = sum * r2 - 1.0 / 720.0;                    // -1/6!
  sum = sum * r2 + 1.0 / 24.0;                     // 1/4!
  sum = sum * r2 - 0.5;                            // -1/2!
  return 1.0 + r2 * sum;
}

// `value` rounded to the nearest integer, ties to even: std::nearbyint in the default rounding
// mode (the only one the engine runs in), without its library call. Below 2^51 in magnitude,
// adding and subtracting 1.5 * 2^52 leaves exactly the rounded value (the sum's last bit is
// worth 1); larger doubles are integers already.
constexpr double kShifter = 6755399441055744.0;  // 1.5 * 2^52

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

typedef double Doubles2 __attribute__((vector_size(16)));  // one SSE2 register
typedef std::int64_t Int64s2 __attribute__((vector_size(16)));

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

void cos_sin_4(const float* angles, CosSin* results) {
  // The vector path covers |angle| < 2^30 (quadrants well inside 2^51 and 2^62, where
  // `nearest_integer` and `quadrant_mod_4` take their exact shortcuts); anything else, and any
  // non-finite angle, goes through cos_sin one lane at a time.
  constexpr float vector_limit = 1073741824.0f;  // 2^30
  bool all_in_range = true;
  for (int lane = 0; lane < 4; ++lane) {
    all_in_range = all_in_range && std::fabs(angles[lane]) < vector_limit;
  }
  if (!all_in_range) {
    for (int lane = 0; lane < 4; ++lane) results[lane] = cos_sin(angles[lane]);
    return;
  }
  for (int half = 0; half < 4; half += 2) {
    const Doubles2 x = {angles[half], angles[half + 1]};
    const Doubles2 quadrant = (x * kTwoOverPi + kShifter) - kShifter;  // nearest_integer's
    const Doubles2 r = (x - quadrant * kHalfPiHigh) - quadrant * kHalfPiLow;
    const Doubles2 s = sine_polynomial(r);
    const Doubles2 c = cosine_polynomial(r);
    const Int64s2 q = __builtin_convertvector(quadrant, Int64s2) & 3;
    for (int lane = 0; lane < 2; ++lane) {
      results[half + lane] = in_quadrant(c[lane], s[lane], q[lane]);
    }
  }
}

}  // namespace impulse2d

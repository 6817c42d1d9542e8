#pragma once
/// @file trig_kernel.h
/// `cos_sin`'s double-precision steps (internal), written once for one double and for vectors
/// of them (the compilers' vector extensions, GCC and Clang): the Cody-Waite range reduction,
/// the Taylor polynomials and the quadrant step, each operation lane by lane in IEEE double
/// precision, no fused multiply-add, so every lane gives the bits one `cos_sin` call gives.
///
/// Included only by trig.cpp (the scalar `cos_sin` and the 2-lane path) and
/// trig_kernel_avx2.cpp (the 4-lane path, compiled with -mavx2). Everything here has internal
/// linkage (the unnamed namespace) and calls no inline function of another header, so the
/// linker never merges an AVX2 copy of a function into code that runs on a CPU without AVX2.

#include "core/trig.h"

#include <cstdint>
#include <cstring>

#if defined(__AVX__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impulse2d {
namespace {

// pi/2 split in two doubles (Cody-Waite): the first has trailing zero bits so that
// quadrant * kHalfPiHigh is exact for quadrants below 2^20; the second carries the rest.
constexpr double kHalfPiHigh = 1.5707963267341256;
constexpr double kHalfPiLow = 6.077100506506192e-11;
constexpr double kTwoOverPi = 0.6366197723675814;

// Adding and subtracting 1.5 * 2^52 rounds a double below 2^51 in magnitude to the nearest
// integer, ties to even (the sum's last bit is worth 1), as std::nearbyint does in the default
// rounding mode (the only one the engine runs in), without its library call. The sum's low
// mantissa bits then hold that integer in two's complement.
constexpr double kShifter = 6755399441055744.0;  // 1.5 * 2^52

// The vector paths cover |angle| < 2^30 (quadrants well inside 2^51, where the shifter rounds
// exactly); `cos_sin` takes any other angle, and any non-finite one, one lane at a time.
constexpr std::int32_t kVectorLimitBits = 0x4e800000;  // 2^30 as a float

// Taylor series on |r| <= pi/4, evaluated by Horner's rule; the first omitted term is below
// 2^-56 of the result.
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

template <int Lanes>
struct TrigLanes;
template <>
struct TrigLanes<2> {
  typedef double Doubles __attribute__((vector_size(16)));
  typedef std::uint64_t Bits __attribute__((vector_size(16)));
  typedef float Floats __attribute__((vector_size(8)));
  typedef float Pairs __attribute__((vector_size(16)));  // cosine, sine, cosine, sine
};
template <>
struct TrigLanes<4> {
  typedef double Doubles __attribute__((vector_size(32)));
  typedef std::uint64_t Bits __attribute__((vector_size(32)));
  typedef float Floats __attribute__((vector_size(16)));
  typedef float Pairs __attribute__((vector_size(32)));
};

// True when all four angles are finite and below 2^30 in magnitude: their bits without the
// sign, compared as integers (every NaN and infinity lies above every finite float).
bool all_in_vector_range(const float* angles) {
  typedef std::int32_t Words __attribute__((vector_size(16)));
  Words bits;
  std::memcpy(&bits, angles, sizeof bits);
  const Words below = (bits & 0x7fffffff) < kVectorLimitBits;  // all ones where in range
#if defined(__SSE2__)
  return _mm_movemask_ps((__m128)below) == 0xf;  // one instruction for the four lanes
#else
  return (below[0] & below[1] & below[2] & below[3]) != 0;
#endif
}

// The floats widened to doubles, exactly.
template <class Doubles, class Floats>
Doubles to_doubles(Floats floats) {
#if defined(__AVX__)
  if constexpr (sizeof(Doubles) == 32) {
    return (Doubles)_mm256_cvtps_pd((__m128)floats);  // GCC 12 splits the generic form in two
  }
#endif
  return __builtin_convertvector(floats, Doubles);
}

// cos and sin of four `angles` into `results`, `Lanes` at a time, as `cos_sin` gives them, for
// angles that pass `all_in_vector_range`. The quadrant step is branch-free: with q the quadrant
// mod 4 and c, s the cosine and sine of the reduced angle, an odd q swaps c and s, the cosine's
// sign flips for q = 1, 2 and the sine's for q = 2, 3 (the sign bit flipped in the double, which
// rounds to the float that negating the rounded float gives).
template <int Lanes>
void cos_sin_4_lanes(const float* angles, CosSin* results) {
  typedef typename TrigLanes<Lanes>::Doubles Doubles;
  typedef typename TrigLanes<Lanes>::Bits Bits;
  typedef typename TrigLanes<Lanes>::Floats Floats;
  typedef typename TrigLanes<Lanes>::Pairs Pairs;
  static_assert(sizeof(CosSin) == 2 * sizeof(float), "CosSin is a pair of floats");
  // One loop over the 2-lane halves, not a call per half: the constants are set up once.
  for (int first = 0; first < 4; first += Lanes) {
    Floats angle;
    std::memcpy(&angle, angles + first, sizeof angle);
    const Doubles x = to_doubles<Doubles>(angle);
    const Doubles shifted = x * kTwoOverPi + kShifter;
    const Doubles quadrant = shifted - kShifter;
    const Doubles r = (x - quadrant * kHalfPiHigh) - quadrant * kHalfPiLow;
    const Bits c = (Bits)cosine_polynomial(r);
    const Bits s = (Bits)sine_polynomial(r);
    const Bits q = (Bits)shifted;  // the quadrant's low bits
    const Bits swap = (c ^ s) & (0 - (q & 1));
    const Bits cosine = (c ^ swap) ^ (((q + 1) >> 1) << 63);
    const Bits sine = (s ^ swap) ^ ((q >> 1) << 63);
    const Floats cosines = __builtin_convertvector((Doubles)cosine, Floats);
    const Floats sines = __builtin_convertvector((Doubles)sine, Floats);
    Pairs pairs;
    if constexpr (Lanes == 2) {
      pairs = __builtin_shufflevector(cosines, sines, 0, 2, 1, 3);
    } else {
      pairs = __builtin_shufflevector(cosines, sines, 0, 4, 1, 5, 2, 6, 3, 7);
    }
    std::memcpy(&results[first].cosine, &pairs, sizeof pairs);  // `Lanes` CosSins, one store
  }
}

}  // namespace
}  // namespace impulse2d

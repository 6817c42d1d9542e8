#pragma once
/// @file trig.h
/// Cosine and sine computed by the engine itself, so that a state update never depends on
/// the C library: libm's last bit differs between versions and CPUs, the engine's does not.
/// Only IEEE-754 double additions and multiplications are used (exactly rounded everywhere,
/// with -ffp-contract=off), so the result is bit-identical on any x86-64 or AArch64 build.

namespace impulse2d {

/// cos(angle) and sin(angle) of one angle in radians.
struct CosSin {
  float cosine = 1.0f;  ///< cos(angle)
  float sine = 0.0f;    ///< sin(angle)
};

/// cos and sin of `angle` (radians), each within one float rounding of the exact value
/// (the double-precision polynomial errs by < 1e-16 on the reduced angle). Exact for 0.
/// Angles beyond 1e9 rad lose accuracy in the range reduction; non-finite angles give NaN.
CosSin cos_sin(float angle);

/// `cos_sin` of four angles (radians) at once, bit for bit as four calls give (the same double
/// operations, lane by lane): `results[i]` for `angles[i]`.
void cos_sin_4(const float* angles, CosSin* results);

}  // namespace impulse2d

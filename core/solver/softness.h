#pragma once
/// @file softness.h
/// The coefficients that turn a rigid velocity constraint into an implicit spring-damper
/// (Box2D v3's "soft constraint"), used by the soft step's contacts.

namespace impulse2d {

/// The three coefficients that turn a rigid velocity constraint into a spring-damper of
/// frequency f (Hz) and damping ratio z over a time step h (s), matching implicit Euler:
/// with w = 2 pi f, bias_rate = w / (2 z + h w), mass_scale = h w (2 z + h w) /
/// (1 + h w (2 z + h w)), impulse_scale = 1 / (1 + h w (2 z + h w)).
struct Softness {
  float bias_rate = 0.0f;      ///< 1/s: target push-out speed per metre of overlap
  float mass_scale = 1.0f;     ///< fraction of the rigid impulse applied
  float impulse_scale = 0.0f;  ///< fraction of the accumulated impulse relaxed each pass
};

/// The softness of a spring of `hertz` (Hz, > 0) and `damping_ratio` over a step of `h` seconds.
Softness make_soft(float hertz, float damping_ratio, float h);

}  // namespace impulse2d

#include "core/solver/softness.h"

namespace impulse2d {

Softness make_soft(float hertz, float damping_ratio, float h) {
  constexpr float two_pi = 6.28318530717958647692f;
  const float omega = two_pi * hertz;
  const float stiffness_term = 2.0f * damping_ratio + h * omega;
  const float implicit_term = h * omega * stiffness_term;
  const float inverse_denominator = 1.0f / (1.0f + implicit_term);
  Softness softness;
  softness.bias_rate = omega / stiffness_term;
  softness.mass_scale = implicit_term * inverse_denominator;
  softness.impulse_scale = inverse_denominator;
  return softness;
}

}  // namespace impulse2d

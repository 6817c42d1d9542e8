#pragma once
/// @file soft_contact_solver.h
/// Soft contact constraints for `SolverMethod::SoftStep` (Box2D v3's solver): the contact is a
/// spring-damper on the separation recomputed from the current positions, solved with
/// accumulated impulses once per sub-step, then relaxed without the spring; restitution is
/// applied once after all sub-steps. Anchors, masses, restitution targets and warm starting
/// come from `contact_solver.h`.

#include "core/body.h"
#include "core/contact.h"
#include "core/settings.h"

#include <vector>

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

/// One pass of soft contacts over a sub-step of `h` seconds. For each point the separation
/// s (m) is recomputed from the current transforms through the point's local anchors; s > 0
/// lets the bodies close the gap within the sub-step (speculative, bias s / h); an overlap
/// with `use_bias` is pushed out softly at max(bias_rate s, -contact_push_max_speed); without
/// `use_bias` (relaxing) the constraint is rigid and adds no push-out speed. Normal impulses
/// stay >= 0; friction follows, clamped to mu_s * Pn while the point sticks and mu_d * Pn once
/// it slides, as in the accumulated solver.
void solve_contacts_soft(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const WorldSettings& settings, float h, bool use_bias);

/// Restitution, once per step after all sub-steps: each point that pushed this step and
/// approached faster than the restitution threshold at prepare gets the normal impulse that
/// makes its separating speed e times that approach speed (accumulated impulse stays >= 0).
void apply_restitution(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                       const WorldSettings& settings);

}  // namespace impulse2d

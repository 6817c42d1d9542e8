#pragma once
/// @file contact_friction_state.h
/// Coulomb's static/dynamic switch, decided for a contact as a whole once per step.
///
/// A contact starts sticking: its accumulated friction impulse is clamped to mu_s * Pn at each
/// point. It breaks loose only when the friction it needs reaches the static limit: every
/// point of the manifold ended the solve clamped at mu_s * Pn (with rotation the two points
/// carry unequal normal impulses, so one saturated point alone only shifts load to the other)
/// and, even so, its slip still grew over the step, on two consecutive steps (the first step
/// of a contact is solved cold and can look saturated before its normal impulses converge). Friction saturated only while clearing
/// residual slip left by an unconverged iterative solve (the slip shrinks) is not "reaching
/// the limit": the contact keeps sticking and the slip dies out.
/// Then its friction drops to mu_d * Pn and it slides until its relative tangential speed is
/// back at rest (at most `sticking_speed`), when it sticks again (stick-slip both ways, the
/// seed's "energy of activation").
///
/// A sticking contact also breaks loose before the solve, in the narrow phase, when the slip
/// its surfaces bring into the step is more than static friction can stop within the step
/// (`static_friction_cannot_stop_slip`): whatever set them moving (an impulse, a collision
/// elsewhere), surfaces that slip rub with mu_d. The after-solve switch above remains for the
/// static limit reached by forces during the step (a push, a slope).

#include "core/body.h"
#include "core/contact.h"
#include "core/settings.h"

#include <vector>

namespace impulse2d {

/// Relative tangential speed (m/s) at or below which a sliding contact counts as back at rest.
constexpr float sticking_speed = 1.0e-3f;

/// True when the sticking `contact` between bodies `a` and `b` cannot stay stuck through the
/// coming step: static friction cannot stop, within the step, the slip its surfaces bring
/// into it. Read before the solve, from the bodies' velocities and the contact's normal
/// impulses carried over from last step (the warm-start values).
///
/// Derivation. A point of relative tangential velocity v_t comes to rest under a tangential
/// impulse of |v_t| m_t, where m_t = 1 / (invA + invB + (rA x t)^2 invIA + (rB x t)^2 invIB)
/// is its effective mass along the tangent t (r: the point's arms from the centres of mass;
/// the inverse inertias are 0 with rotation off, as the solvers take them). The contact needs
/// the mean of that over its points, J_need = mean_i(|v_t,i| m_t,i). Within the step static
/// friction can deliver at most mu_s * Pn, Pn the contact's normal impulse over the step; the
/// load it carried last step, sum_i(Pn_i) times `impulse_intervals` (the number of impulse
/// intervals in one narrow-phase interval: the soft step accumulates its impulses per sub-step
/// but collides once per step), is its best estimate before the solve. If J_need exceeds it,
/// friction at the static limit for the whole step still leaves the surfaces slipping: the
/// contact slides from the start of the step (mu_d). The per-point mass is the smaller for a
/// rotating body (at a box's corner m_t ~ 0.4 m), while two points sliding together need about
/// the linear m v (the other point's normal row resists the turn), so the mean errs toward
/// sticking: it never breaks loose a contact that could hold, and what it leaves stuck the
/// after-solve switch judges. Scale: a box resting on the ground carries Pn = W dt, so it
/// breaks loose at once when |v_t| > mu_s g dt m / m_t (8 cm/s at 60 Hz and mu_s 0.5 for a
/// non-rotating box); the residual slip of an unconverged solve in a stack or of a block held
/// on a slope is ~1 mm/s, far below. Slip at or below `sticking_speed` is rest: never loose.
bool static_friction_cannot_stop_slip(const Contact& contact, const Body& a, const Body& b,
                                      bool rotation, float impulse_intervals);

/// The narrow phase's carry-over of a kept contact (`contact` already holds last step's state
/// and impulses): a sticking contact for which `static_friction_cannot_stop_slip` holds
/// starts the step sliding, its carried friction impulses clamped to mu_d * Pn so the warm
/// start applies no more than the dynamic limit. A no-op for PerIteration (it decides the
/// state afresh in every iteration and keeps no impulses) and with friction off.
void break_loose_if_slipping(Contact& contact, const Body& a, const Body& b,
                             const WorldSettings& settings);

/// Applies the switch to every contact after the step's velocity solve: sticking contacts at
/// the static limit break loose (their friction impulses drop to mu_d * Pn and the difference
/// is applied); sliding contacts at rest stick again.
void update_friction_state(std::vector<Contact>& contacts, std::vector<Body>& bodies);

/// The switch for one solvable contact between bodies `a` and `b` (see above), for solvers that
/// walk the contacts for more than this.
void update_friction_state(Contact& contact, Body& a, Body& b);

}  // namespace impulse2d

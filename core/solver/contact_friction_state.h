#pragma once
/// @file contact_friction_state.h
/// Coulomb's static/dynamic switch, decided for a contact as a whole once per step.
///
/// A contact starts sticking: its accumulated friction impulse is clamped to mu_s * Pn (the
/// soft step: at the contact's middle, against the two points' total load). It breaks loose
/// only when the friction it needs reaches the static limit: every point ended the solve at the
/// limit and, even so, its slip grew over the step by more than the step's change of load can
/// explain (a limit mu_s * Pn off by mu_s |dPn| lets the slip grow by that over the tangent
/// mass: a cold start, a landing), on two consecutive steps. Friction saturated only while
/// clearing residual slip left by an unconverged iterative solve (the slip shrinks) is not
/// "reaching the limit": the contact keeps sticking and the slip dies out.
/// Then its friction drops to mu_d * Pn and it slides until its relative tangential speed is
/// back at rest (at most `sticking_speed`), when it sticks again (stick-slip both ways, the
/// seed's "energy of activation").
///
/// A sticking contact also breaks loose before the solve, as it is prepared, when the slip
/// its surfaces bring into the step is more than static friction can stop within the step
/// (`static_friction_cannot_stop`): whatever set them moving (an impulse, a collision
/// elsewhere), surfaces that slip rub with mu_d. The after-solve switch above remains for the
/// static limit reached by forces during the step (a push, a slope).

#include "core/solver/body_state.h"
#include "core/contact.h"

#include <vector>

namespace impulse2d {

/// Relative tangential speed (m/s) at or below which a sliding contact counts as back at rest.
constexpr float sticking_speed = 1.0e-3f;

/// True when a sticking contact cannot stay stuck through the coming step: static friction
/// cannot stop, within the step, the slip its surfaces bring into it. `needed` (N s) is the
/// mean over its points of |v_t| m_t, the tangential impulse that would bring each point's
/// slip to rest; `carried_load` (N s) the sum of its normal impulses carried over from last
/// step (the warm-start values); `impulse_intervals` how many impulse intervals one prepare
/// covers (the soft step prepares once a step but accumulates its impulses per sub-step; the
/// other solvers prepare every (sub-)step). `prepare_contact` evaluates it.
///
/// Derivation. A point of relative tangential velocity v_t comes to rest under a tangential
/// impulse of |v_t| m_t, where m_t = 1 / (invA + invB + (rA x t)^2 invIA + (rB x t)^2 invIB)
/// is its effective mass along the tangent t. Within the step static friction can deliver at
/// most mu_s * Pn, Pn the contact's normal impulse over the step, whose best estimate before
/// the solve is the load carried last step times `impulse_intervals`. If the need exceeds it,
/// friction at the static limit for the whole step still leaves the surfaces slipping: the
/// contact slides from the start of the step (mu_d). The per-point mass is the smaller for a
/// rotating body (at a box's corner m_t ~ 0.4 m), while two points sliding together need about
/// the linear m v, so the mean errs toward sticking: it never breaks loose a contact that could
/// hold, and what it leaves stuck the after-solve switch judges. Scale: a box resting on the
/// ground carries Pn = W dt, so it breaks loose at once when |v_t| > mu_s g dt m / m_t (8 cm/s
/// at 60 Hz and mu_s 0.5 for a non-rotating box); the residual slip of an unconverged solve in
/// a stack or of a block held on a slope is ~1 mm/s, far below.
inline bool static_friction_cannot_stop(float needed, float carried_load, float static_friction,
                                        float impulse_intervals) {
  return needed > static_friction * impulse_intervals * carried_load;
}

/// Starts `contact` sliding before the solve (see `static_friction_cannot_stop`), its carried
/// friction impulses clamped to mu_d * Pn so the warm start applies no more than the dynamic
/// limit.
void break_loose(Contact& contact);

/// Applies the switch to every contact after the step's velocity solve: sticking contacts at
/// the static limit break loose (their friction impulses drop to mu_d * Pn and the difference
/// is applied); sliding contacts at rest stick again.
void update_friction_state(std::vector<Contact>& contacts, std::vector<Body>& bodies);

/// The switch for one solvable contact between bodies `a` and `b` (see above), for solvers that
/// walk the contacts for more than this.
void update_friction_state(Contact& contact, Body& a, Body& b);

}  // namespace impulse2d

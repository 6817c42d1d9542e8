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

#include "core/body.h"
#include "core/contact.h"

#include <vector>

namespace impulse2d {

/// Relative tangential speed (m/s) at or below which a sliding contact counts as back at rest.
constexpr float sticking_speed = 1.0e-3f;

/// Applies the switch to every contact after the step's velocity solve: sticking contacts at
/// the static limit break loose (their friction impulses drop to mu_d * Pn and the difference
/// is applied); sliding contacts at rest stick again.
void update_friction_state(std::vector<Contact>& contacts, std::vector<Body>& bodies);

/// The switch for one solvable contact between bodies `a` and `b` (see above), for solvers that
/// walk the contacts for more than this.
void update_friction_state(Contact& contact, Body& a, Body& b);

}  // namespace impulse2d

#pragma once
/// @file contact_solver.h
/// Velocity-level contact impulses: normal (non-penetration, restitution) and Coulomb friction
/// with static and dynamic coefficients, in the two forms of `SolverMethod`.

#include "core/body.h"
#include "core/contact.h"
#include "core/settings.h"

#include <vector>

namespace impulse2d {

/// Relative speed (m/s) along the tangent below which a contact point counts as sticking at the
/// end of a step, so the next step starts it with the static coefficient.
constexpr float sticking_speed = 1.0e-3f;

/// Computes anchors, effective masses and restitution targets of every contact point from the
/// current transforms and velocities. Without warm starting (or with the per-iteration
/// method) it also zeroes the carried-over impulses.
void prepare_contacts(std::vector<Contact>& contacts, const std::vector<Body>& bodies,
                      const WorldSettings& settings);

/// Applies the carried-over accumulated impulses (warm starting).
void warm_start_contacts(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const WorldSettings& settings);

/// One pass of sequential impulses with accumulated, clamped impulses: friction (limit
/// mu_s * Pn while sticking, mu_d * Pn once sliding), then the normal impulse (Pn >= 0).
void solve_contacts_accumulated(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                const WorldSettings& settings);

/// One pass of the tutorial's impulses: for each point, a fresh normal impulse
/// j = -(1 + e) vn / K (skipped while separating), then friction along the current tangential
/// velocity: jt if |jt| < j mu_s (sticking), else -j mu_d (sliding).
void solve_contacts_per_iteration(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                  const WorldSettings& settings);

/// Ends the accumulated-impulse solve with Coulomb's static/dynamic switch: a sticking contact
/// whose points all ended clamped at mu_s * Pn has broken loose, so each point's friction
/// impulse drops to mu_d * Pn (the difference is applied) and it starts the next step sliding.
void break_static_friction(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                           const WorldSettings& settings);

/// Records, for each point, whether it still slides after the velocity solve: the relative
/// tangential speed exceeds `sticking_speed`, or static friction just broke.
void update_sliding_state(std::vector<Contact>& contacts, const std::vector<Body>& bodies);

}  // namespace impulse2d

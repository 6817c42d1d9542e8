#pragma once
/// @file soft_contact_solver.h
/// Soft contact constraints for `SolverMethod::SoftStep` (Box2D v3's solver): the contact is a
/// spring-damper on the separation recomputed from the current positions, solved with
/// accumulated impulses, then relaxed without the spring.

#include "core/body.h"
#include "core/contact.h"
#include "core/softness.h"
#include "core/solver_context.h"

#include <vector>

namespace impulse2d {

/// One pass of soft contacts over a sub-step. For each point the separation s (m) is
/// recomputed from the current transforms through the point's local anchors; s > 0 lets the
/// bodies close the gap within the sub-step (speculative, vn >= -s / h); an overlap with
/// `use_bias` is pushed out softly at min(bias_rate |s|, push_max_speed) (twice as stiff
/// against a static or kinematic body); without `use_bias` (relaxing) the constraint is rigid
/// and adds no push-out speed, and points still apart are left alone. A point bouncing in this sub-step keeps the rigid target of its
/// bounce (`contact_bounce.h`). Normal impulses stay >= 0. In the relax pass friction follows,
/// clamped to mu_s * Pn while the contact sticks and mu_d * Pn once it slides.
void solve_contacts_soft(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const SolverContext& context, bool use_bias);

}  // namespace impulse2d

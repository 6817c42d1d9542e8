#pragma once
/// @file contact_solver_internal.h
/// Helpers shared by the contact solvers only (not part of the public API): relative velocity
/// at a point, impulse application, effective mass, and the accumulated normal and friction
/// updates of one point.

#include "core/solver/body_state.h"
#include "core/contact.h"

#include <algorithm>
#include <vector>

namespace impulse2d {
namespace contact_detail {

/// Velocity (m/s) of B's point relative to A's point, at the point's anchors.
inline vec2 relative_velocity(const Body& a, const Body& b, const ContactPoint& point) {
  const vec2 velocity_b = b.linear_velocity + cross(b.angular_velocity, point.anchor_b);
  const vec2 velocity_a = a.linear_velocity + cross(a.angular_velocity, point.anchor_a);
  return velocity_b - velocity_a;
}

/// Applies `impulse` (N s) to B at its anchor and the opposite to A.
inline void apply_impulse(Body& a, Body& b, const PairMass& mass, const ContactPoint& point,
                          vec2 impulse) {
  a.linear_velocity -= impulse * mass.inverse_mass_a;
  a.angular_velocity -= mass.inverse_inertia_a * cross(point.anchor_a, impulse);
  b.linear_velocity += impulse * mass.inverse_mass_b;
  b.angular_velocity += mass.inverse_inertia_b * cross(point.anchor_b, impulse);
}

/// 1 / (effective mass) along `direction` at a point, 1/kg:
/// invA + invB + (rA x d)^2 invIA + (rB x d)^2 invIB.
inline float inverse_effective_mass(const PairMass& mass, const ContactPoint& point, vec2 direction) {
  const float arm_a = cross(point.anchor_a, direction);
  const float arm_b = cross(point.anchor_b, direction);
  return mass.inverse_mass_a + mass.inverse_mass_b + arm_a * arm_a * mass.inverse_inertia_a +
         arm_b * arm_b * mass.inverse_inertia_b;
}

/// True when the contact's impulses move body A (it has a finite mass or inertia there).
inline bool moves_a(const PairMass& mass) {
  return mass.inverse_mass_a > 0.0f || mass.inverse_inertia_a > 0.0f;
}

/// True when the contact's impulses move body B.
inline bool moves_b(const PairMass& mass) {
  return mass.inverse_mass_b > 0.0f || mass.inverse_inertia_b > 0.0f;
}

/// True when the contact is enabled and at least one of its bodies can move.
inline bool is_solvable(const Contact& contact) {
  return contact.enabled &&
         (contact.mass.inverse_mass_a > 0.0f || contact.mass.inverse_mass_b > 0.0f);
}

/// The fixed friction direction of a contact: the normal turned clockwise.
inline vec2 tangent_of(vec2 normal) { return right_perpendicular(normal); }

/// Raises the point's accumulated normal impulse (kept >= 0) so that its relative normal
/// velocity reaches `target_speed` (m/s), and applies the change.
inline void push_normal_to(Body& a, Body& b, const Contact& contact, ContactPoint& point,
                           float target_speed) {
  const float normal_speed = glm::dot(relative_velocity(a, b, point), contact.normal);
  const float accumulated =
      std::max(point.normal_impulse - (normal_speed - target_speed) * point.normal_mass, 0.0f);
  const float change = accumulated - point.normal_impulse;
  point.normal_impulse = accumulated;
  apply_impulse(a, b, contact.mass, point, contact.normal * change);
}

/// Tangential offset (m) of the point's anchor on B from its anchor on A, along the contact's
/// tangent, less the offset at which the point last stuck.
inline float friction_drift(const Body& a, const Body& b, const Contact& contact,
                            const ContactPoint& point) {
  const vec2 on_a = a.transform.apply(point.recycle_anchor_a);
  const vec2 on_b = b.transform.apply(point.recycle_anchor_b);
  return glm::dot(on_b - on_a, tangent_of(contact.normal)) - point.stick_offset;
}

/// One pass of Coulomb friction over a contact's points with accumulated impulses: the
/// accumulated tangent impulse is clamped to mu_s * Pn while the contact sticks and mu_d * Pn
/// once it slides; `friction_at_limit` records whether the clamp acted.
inline void solve_friction_points(Body& a, Body& b, Contact& contact) {
  const vec2 tangent = tangent_of(contact.normal);
  const float coefficient = contact.sliding ? contact.dynamic_friction : contact.static_friction;
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const float tangent_speed = glm::dot(relative_velocity(a, b, point), tangent);
    const float unclamped = point.tangent_impulse - tangent_speed * point.tangent_mass;
    const float limit = coefficient * point.normal_impulse;
    const float accumulated = std::clamp(unclamped, -limit, limit);
    point.friction_at_limit = accumulated != unclamped;
    const float change = accumulated - point.tangent_impulse;
    point.tangent_impulse = accumulated;
    apply_impulse(a, b, contact.mass, point, tangent * change);
  }
}

}  // namespace contact_detail
}  // namespace impulse2d

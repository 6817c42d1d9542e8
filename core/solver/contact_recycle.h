#pragma once
/// @file contact_recycle.h
/// Contact recycling (Box2D v3's name; PhysX keeps persistent manifolds the same way): while a
/// pair's relative pose has changed by less than `WorldSettings::contact_recycle_distance`
/// since its manifold was computed, the manifold is kept instead of collided afresh. The
/// normal stays where it was, each point stays fixed in both bodies (its anchors turn with
/// them), and only the separation is updated from how far the two anchors moved along the
/// normal - the way the soft step tracks separation between its sub-steps.
///
/// Why it matters beyond speed: with manifolds collided afresh every step, a 20-box soft-step
/// stack leans further step after step and falls within 15 s (Box2D v3 does the same with its
/// recycling switched off); with recycled manifolds solved at the offsets they were found
/// with (`set_recycled_anchors`), its sway decays as Box2D v3's does.

#include "core/solver/body_state.h"
#include "core/contact.h"

namespace impulse2d {

/// Records the bodies' pose and each point's anchors and separation for later recycling;
/// call when `contact`'s manifold has just been computed at the bodies' current transforms.
void remember_manifold_pose(const Body& a, const Body& b, Contact& contact);

/// True when `contact`'s manifold may be kept for bodies `a` and `b` as they stand now: both
/// bodies allow it (dynamic or fixed, speculative, not bullets), the contact is enabled, and
/// since the manifold was computed each body turned by less than 11.5 degrees and the relative
/// pose moved by less than `recycle_distance` metres (the offset of B's centre in A's frame plus
/// the largest body extent times the sine of the relative turn, conservative advancement's
/// bound on how far a surface point moved) - or, when no point was touching (all speculative),
/// by less than the smaller of that and `apart_distance` (the speculative margin, so that a
/// gap closing fast is collided afresh before it can be missed).
bool may_recycle(const Body& a, const Body& b, const Contact& contact, float recycle_distance,
                 float apart_distance);

/// Updates a kept manifold for the bodies' current transforms: each point's world position
/// (midway between its two anchors) and depth (minus the base separation and the anchors'
/// relative motion along the unchanged normal).
void recycle_manifold(const Body& a, const Body& b, Contact& contact);

/// The anchors a kept point is solved with this step (Box2D v3's): `anchor_a` and `anchor_b`
/// are the offsets from each body's centre to the point as they were when the manifold was
/// computed, not turned with the bodies since; `local_anchor_a/b` are the core points under
/// the ends of those offsets now (`core_anchor`: a circle's centre), B's (for a circle B, A's)
/// moved along the normal so that their separation starts the step at the recycled depth. Turning the offsets with the bodies instead (the points
/// fixed in the material) let a 20-box soft-step stack lean over within 15 s, as collision
/// afresh every step does; with the offsets kept it stands like Box2D v3's (3 cm of sway).
/// Defined here so that the per-point prepare loop inlines it.
inline void set_recycled_anchors(const Body& a, const Body& b, const Contact& contact, ContactPoint& point) {
  point.anchor_a = contact.manifold_pose.rotation_a.rotate(point.recycle_anchor_a);
  point.anchor_b = contact.manifold_pose.rotation_b.rotate(point.recycle_anchor_b);
  const vec2 normal = contact.normal;
  const bool round_a = is_circle(a, contact.child_a);
  const bool round_b = is_circle(b, contact.child_b);
  // The core points (see `core_anchor`) under the ends of the offsets: a circle's centre.
  auto centre_of = [](const Body& body, int child) {
    return body.compound ? body.transform.apply(local_centre(body, child)) : body.transform.position;
  };
  vec2 core_a = round_a ? centre_of(a, contact.child_a)
                        : a.transform.position + point.anchor_a - normal * rounding_of(a, contact.child_a);
  vec2 core_b = round_b ? centre_of(b, contact.child_b)
                        : b.transform.position + point.anchor_b + normal * rounding_of(b, contact.child_b);
  // B's core (or, for a circle B, A's) moves along the normal so that the separation starts
  // the step at the recycled depth; two circles' centres give their separation exactly.
  const float excess = glm::dot(core_b - core_a, normal) - point.rounding + point.depth;
  if (!round_b) {
    core_b -= normal * excess;
  } else if (!round_a) {
    core_a += normal * excess;
  }
  point.local_anchor_a = round_a ? local_centre(a, contact.child_a) : a.transform.apply_inverse(core_a);
  point.local_anchor_b = round_b ? local_centre(b, contact.child_b) : b.transform.apply_inverse(core_b);
}

}  // namespace impulse2d

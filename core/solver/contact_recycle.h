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
/// with (`set_recycled_offsets`), its sway decays as Box2D v3's does.

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

/// What a kept manifold's points need of the two shapes under them, the same for every point
/// of the contact: found once per contact (`recycled_shapes_of`), not once per point.
struct RecycledShapes {
  bool round_a = false;   ///< A's shape is a circle: its core point is its centre
  bool round_b = false;   ///< B's shape is a circle
  float rounding_a = 0.0f;  ///< A's shape's rounding, metres (`rounding_of`)
  float rounding_b = 0.0f;  ///< B's shape's rounding, metres
  vec2 local_centre_a{0.0f, 0.0f};  ///< centre of A's shape in A's frame, metres (`local_centre`)
  vec2 local_centre_b{0.0f, 0.0f};  ///< centre of B's shape in B's frame, metres
  vec2 centre_a{0.0f, 0.0f};  ///< centre of A's shape in the world, metres (used where round)
  vec2 centre_b{0.0f, 0.0f};  ///< centre of B's shape in the world, metres (used where round)
};

/// The shapes under `contact`'s points as `set_recycled_cores` reads them, at the bodies'
/// current transforms.
inline RecycledShapes recycled_shapes_of(const Body& a, const Body& b, const Contact& contact) {
  RecycledShapes shapes;
  shapes.round_a = is_circle(a, contact.child_a);
  shapes.round_b = is_circle(b, contact.child_b);
  shapes.rounding_a = rounding_of(a, contact.child_a);
  shapes.rounding_b = rounding_of(b, contact.child_b);
  shapes.local_centre_a = local_centre(a, contact.child_a);
  shapes.local_centre_b = local_centre(b, contact.child_b);
  shapes.centre_a = a.compound ? a.transform.apply(shapes.local_centre_a) : a.transform.position;
  shapes.centre_b = b.compound ? b.transform.apply(shapes.local_centre_b) : b.transform.position;
  return shapes;
}

/// The offsets a kept point is solved with this step (Box2D v3's): from each body's centre to
/// the point as they were when the manifold was computed, not turned with the bodies since.
/// They change only when the manifold is computed afresh. Turning the offsets with the bodies
/// instead (the points fixed in the material) let a 20-box soft-step stack lean over within
/// 15 s, as collision afresh every step does; with the offsets kept it stands like Box2D v3's
/// (3 cm of sway).
inline void set_recycled_offsets(const Contact& contact, ContactPoint& point) {
  point.anchor_a = contact.manifold_pose.rotation_a.rotate(point.recycle_anchor_a);
  point.anchor_b = contact.manifold_pose.rotation_b.rotate(point.recycle_anchor_b);
}

/// The core points (`local_anchor_a/b`, see `core_anchor`: a circle's centre) under the ends
/// of a kept point's offsets (`set_recycled_offsets`) now, B's (for a circle B, A's) moved along
/// the normal so that their separation starts the step at the recycled depth. Defined here so
/// that the per-point prepare loop inlines it.
inline void set_recycled_cores(const Body& a, const Body& b, const Contact& contact,
                               const RecycledShapes& shapes, ContactPoint& point) {
  const vec2 normal = contact.normal;
  vec2 core_a = shapes.round_a ? shapes.centre_a : a.transform.position + point.anchor_a - normal * shapes.rounding_a;
  vec2 core_b = shapes.round_b ? shapes.centre_b : b.transform.position + point.anchor_b + normal * shapes.rounding_b;
  // Two circles' centres give their separation exactly.
  const float excess = glm::dot(core_b - core_a, normal) - point.rounding + point.depth;
  if (!shapes.round_b) {
    core_b -= normal * excess;
  } else if (!shapes.round_a) {
    core_a += normal * excess;
  }
  point.local_anchor_a = shapes.round_a ? shapes.local_centre_a : a.transform.apply_inverse(core_a);
  point.local_anchor_b = shapes.round_b ? shapes.local_centre_b : b.transform.apply_inverse(core_b);
}

}  // namespace impulse2d

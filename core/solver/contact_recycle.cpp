#include "core/solver/contact_recycle.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

// Cosine of the largest turn a body may make before its manifold is computed afresh
// (Box2D v3's 0.98: about 11.5 degrees).
constexpr float min_turn_cosine = 0.98f;

// B's centre in A's frame (A's centre in B's frame when only B is static: measured in a turning
// body's frame, a fixed body's centre seems to stay put while the body rolls over it).
vec2 relative_position_of(const Body& a, const Body& b) {
  if (b.type == BodyType::Static && a.type != BodyType::Static) {
    return b.transform.rotation.inverse_rotate(a.transform.position - b.transform.position);
  }
  return a.transform.rotation.inverse_rotate(b.transform.position - a.transform.position);
}

// Where the bodies stand now: their relative position and both rotations.
ManifoldPose pose_of(const Body& a, const Body& b) {
  ManifoldPose pose;
  pose.relative_position = relative_position_of(a, b);
  pose.rotation_a = a.transform.rotation;
  pose.rotation_b = b.transform.rotation;
  return pose;
}

// Rotation `qb` relative to rotation `qa`.
Rotation relative_rotation(const Rotation& qa, const Rotation& qb) {
  return {qa.cosine * qb.cosine + qa.sine * qb.sine, qa.cosine * qb.sine - qa.sine * qb.cosine};
}

// Cosine of the angle between two rotations.
float cosine_between(const Rotation& p, const Rotation& q) {
  return p.cosine * q.cosine + p.sine * q.sine;
}

// Sine of the angle from rotation q to rotation p.
float sine_between(const Rotation& p, const Rotation& q) {
  return p.sine * q.cosine - p.cosine * q.sine;
}

// True when the body's contacts may keep their manifolds at all.
bool allows_recycling(const Body& body) {
  return body.speculative && !body.is_bullet;
}

}  // namespace

void remember_manifold_pose(const Body& a, const Body& b, Contact& contact) {
  contact.manifold_pose = pose_of(a, b);
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    point.recycle_anchor_a = a.transform.apply_inverse(point.point);
    point.recycle_anchor_b = b.transform.apply_inverse(point.point);
    point.base_separation = -point.depth;
    point.stick_offset = 0.0f;
  }
}

bool may_recycle(const Body& a, const Body& b, const Contact& contact, float recycle_distance,
                 float apart_distance) {
  if (!(recycle_distance > 0.0f) || !contact.enabled) return false;
  if (!allows_recycling(a) || !allows_recycling(b)) return false;
  // Read in place: a `ManifoldPose` of now would be copied out to the stack and back.
  const ManifoldPose& then = contact.manifold_pose;
  const Rotation& rotation_a = a.transform.rotation;
  const Rotation& rotation_b = b.transform.rotation;
  const float turn_cosine = std::min(cosine_between(rotation_a, then.rotation_a),
                                     cosine_between(rotation_b, then.rotation_b));
  if (!(turn_cosine > min_turn_cosine)) return false;
  bool touching = false;
  for (int i = 0; i < contact.point_count; ++i) touching = touching || contact.points[i].depth >= 0.0f;
  const float tolerance = touching ? recycle_distance : std::min(recycle_distance, apart_distance);
  const float moved = std::sqrt(length_squared(relative_position_of(a, b) - then.relative_position));
  // The turn's share below is >= 0, so a shift alone at the tolerance already fails (and the
  // shapes' extents need not be looked up).
  if (!(moved < tolerance)) return false;
  const float turned = std::fabs(sine_between(relative_rotation(rotation_a, rotation_b),
                                              relative_rotation(then.rotation_a, then.rotation_b)));
  const float extent_a = a.type == BodyType::Static ? 0.0f : a.extent;
  const float extent_b = b.type == BodyType::Static ? 0.0f : b.extent;
  return moved + std::max(extent_a, extent_b) * turned < tolerance;
}

void recycle_manifold(const Body& a, const Body& b, Contact& contact) {
  // Copies: the stores into `contact` below cannot then make the compiler reload them.
  const Transform xa = a.transform;
  const Transform xb = b.transform;
  const vec2 normal = contact.normal;
  // The point midway between its two surface points, and its depth from how far they moved
  // along the normal.
  auto update = [normal](ContactPoint& point, vec2 on_a, vec2 on_b) {
    point.point = 0.5f * (on_a + on_b);
    point.depth = -(point.base_separation + glm::dot(on_b - on_a, normal));
  };
  const bool round_a = is_circle(a, contact.child_a);
  const bool round_b = is_circle(b, contact.child_b);
  if (!round_a && !round_b) {
    // The common case, on its own: without the circles' cases beside it in the loop, the
    // compiler keeps it short.
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      update(point, xa.apply(point.recycle_anchor_a), xb.apply(point.recycle_anchor_b));
    }
    return;
  }
  // A circle's point stays where it was relative to its centre as the circle turns (the normal
  // is kept): its offset is turned by the rotation it was found at, not the current one.
  // (A compound's circle: its centre moves with the body, the point is kept where it was
  // relative to that centre.)
  const vec2 centre_a = local_centre(a, contact.child_a);
  const vec2 centre_b = local_centre(b, contact.child_b);
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const vec2 on_a =
        !round_a ? xa.apply(point.recycle_anchor_a)
        : a.compound ? xa.apply(centre_a) + contact.manifold_pose.rotation_a.rotate(point.recycle_anchor_a - centre_a)
                     : xa.position + contact.manifold_pose.rotation_a.rotate(point.recycle_anchor_a);
    const vec2 on_b =
        !round_b ? xb.apply(point.recycle_anchor_b)
        : b.compound ? xb.apply(centre_b) + contact.manifold_pose.rotation_b.rotate(point.recycle_anchor_b - centre_b)
                     : xb.position + contact.manifold_pose.rotation_b.rotate(point.recycle_anchor_b);
    update(point, on_a, on_b);
  }
}

}  // namespace impulse2d

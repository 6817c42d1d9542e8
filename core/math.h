#pragma once
/// @file math.h
/// 2D vector helpers on GLM: cross products, rotations and rigid transforms.

#include <glm/vec2.hpp>
#include <glm/geometric.hpp>

#include <cmath>

#include "core/trig.h"

namespace impulse2d {

using glm::vec2;

/// 2D cross product of two vectors: the z component of (a, 0) x (b, 0).
inline float cross(vec2 a, vec2 b) { return a.x * b.y - a.y * b.x; }

/// Cross product of a vector with a scalar z axis value: a x (0, 0, s) = (s a.y, -s a.x).
inline vec2 cross(vec2 a, float s) { return vec2(s * a.y, -s * a.x); }

/// Cross product of a scalar z axis value with a vector: (0, 0, s) x a = (-s a.y, s a.x).
/// Used for the velocity of a point on a spinning body: w x r.
inline vec2 cross(float s, vec2 a) { return vec2(-s * a.y, s * a.x); }

/// Squared length of a vector.
inline float length_squared(vec2 v) { return glm::dot(v, v); }

/// The vector rotated +90 degrees (counter-clockwise).
inline vec2 left_perpendicular(vec2 v) { return vec2(-v.y, v.x); }

/// The vector rotated -90 degrees (clockwise).
inline vec2 right_perpendicular(vec2 v) { return vec2(v.y, -v.x); }

/// True when both components are finite (not NaN, not infinite).
inline bool is_finite(vec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

/// A rotation in the plane stored as cosine and sine of the angle.
struct Rotation {
  float cosine = 1.0f;  ///< cos(angle)
  float sine = 0.0f;    ///< sin(angle)

  /// The rotation by `angle` radians counter-clockwise, from the engine's own `cos_sin`
  /// (never libm's, whose last bit varies between machines).
  static Rotation from_angle(float angle) {
    const CosSin values = cos_sin(angle);
    return {values.cosine, values.sine};
  }
  /// Rotates a vector by this rotation.
  vec2 rotate(vec2 v) const { return vec2(cosine * v.x - sine * v.y, sine * v.x + cosine * v.y); }
  /// Rotates a vector by the inverse of this rotation.
  vec2 inverse_rotate(vec2 v) const { return vec2(cosine * v.x + sine * v.y, -sine * v.x + cosine * v.y); }
  /// The body's local x axis in world coordinates.
  vec2 x_axis() const { return vec2(cosine, sine); }
};

/// A rigid transform: rotate, then translate.
struct Transform {
  vec2 position{0.0f, 0.0f};  ///< translation, metres
  Rotation rotation;          ///< orientation

  /// Maps a point from local to world coordinates.
  vec2 apply(vec2 local_point) const { return rotation.rotate(local_point) + position; }
  /// Maps a point from world to local coordinates.
  vec2 apply_inverse(vec2 world_point) const { return rotation.inverse_rotate(world_point - position); }
};

/// `outer` after `inner`: the frame `inner` (given in `outer`'s frame) in `outer`'s parent's
/// coordinates (a compound body's shape placed in the world).
inline Transform compose(const Transform& outer, const Transform& inner) {
  const Rotation& p = outer.rotation;
  const Rotation& q = inner.rotation;
  return Transform{outer.apply(inner.position),
                   Rotation{p.cosine * q.cosine - p.sine * q.sine, p.sine * q.cosine + p.cosine * q.sine}};
}

}  // namespace impulse2d

#pragma once
/// @file query.h
/// What world queries take and give beyond the ray casts of world.h: a filter (layer mask,
/// sensors, a callback), shape-cast hits, and the distance between two placed shapes that the
/// shape cast is built on (GJK on the shapes' vertices, circles as a point and a radius).

#include "core/body.h"
#include "core/shape.h"

#include <cstdint>
#include <functional>

namespace impulse2d {

/// Which bodies a query considers. The default takes every body but sensors.
struct QueryFilter {
  std::uint32_t layers = 0xFFFFFFFFu;  ///< only bodies whose collision layers share a bit
  bool include_sensors = false;        ///< sensors are skipped unless this is set
  bool include_static = true;          ///< static bodies are considered
  /// Called for each body that passed the other tests; return false to skip it. May be empty.
  /// (A lambda capturing up to two pointers fits std::function's own storage: no allocation.)
  std::function<bool(BodyId)> accept;
};

/// The first hit of a shape moved along a translation (`World::cast_shape`).
struct ShapeCastHit {
  BodyId body;               ///< the body hit first (ties: smallest slot)
  vec2 point{0.0f, 0.0f};    ///< world point on that body's surface where it is met, metres
  /// Unit surface normal of the body hit at `point`, pointing back at the moving shape; for a
  /// shape that overlaps at the start, minus the translation's direction.
  vec2 normal{0.0f, 0.0f};
  float fraction = 0.0f;     ///< of the translation travelled at first touch, in [0, 1]
};

/// Distance between two placed convex shapes.
struct ShapeDistance {
  float distance = 0.0f;      ///< metres between the surfaces; 0 when they overlap or touch
  vec2 point_a{0.0f, 0.0f};   ///< closest point on A's surface, metres (valid when apart)
  vec2 point_b{0.0f, 0.0f};   ///< closest point on B's surface, metres (valid when apart)
  vec2 normal{0.0f, 0.0f};    ///< unit, from A towards B (valid when apart)
};

/// The distance between shape `a` placed at `xa` and `b` at `xb` (GJK; a Box turns with its
/// transform's rotation here). Pure; allocates nothing.
ShapeDistance shape_distance(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb);

}  // namespace impulse2d

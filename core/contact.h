#pragma once
/// @file contact.h
/// A persistent contact between two bodies: the manifold plus the solver's per-point memory.

#include "core/body.h"
#include "core/manifold.h"

#include <cstdint>

namespace impulse2d {

/// The solver's state for one manifold point.
struct ContactPoint {
  vec2 point{0.0f, 0.0f};      ///< world position, metres
  vec2 anchor_a{0.0f, 0.0f};   ///< point relative to A's centre of mass, metres
  vec2 anchor_b{0.0f, 0.0f};   ///< point relative to B's centre of mass, metres
  vec2 local_anchor_a{0.0f, 0.0f};  ///< A's surface point in A's frame (position correction, SoftStep's separation)
  vec2 local_anchor_b{0.0f, 0.0f};  ///< B's surface point in B's frame (position correction, SoftStep's separation)
  float depth = 0.0f;          ///< penetration at detection, metres
  std::uint32_t feature_id = 0;     ///< identifies the point across steps
  float normal_impulse = 0.0f;      ///< accumulated (or last) normal impulse, N s
  float tangent_impulse = 0.0f;     ///< accumulated (or last) friction impulse, N s
  float normal_mass = 0.0f;         ///< 1 / effective mass along the normal, 1/kg
  float tangent_mass = 0.0f;        ///< 1 / effective mass along the tangent, 1/kg
  /// Target separating speed from restitution, m/s: -e times the relative normal velocity at
  /// prepare when that approach is faster than the restitution threshold, else 0.
  float velocity_bias = 0.0f;
  /// SoftStep: the largest normal impulse increment applied this step, N s; restitution is
  /// applied only to points that pushed.
  float max_normal_impulse = 0.0f;
  bool sliding = false;             ///< true once friction switched to the dynamic coefficient
  bool friction_at_limit = false;   ///< the last friction pass was clamped by the Coulomb limit
  bool matched = false;             ///< true when warm-started from the previous step
};

/// A touching pair of bodies. Body A has the smaller slot index.
struct Contact {
  BodyId body_a;   ///< first body (smaller index)
  BodyId body_b;   ///< second body
  vec2 normal{0.0f, 0.0f};  ///< unit, from A to B
  ContactPoint points[max_manifold_points];  ///< the first `point_count` are valid
  int point_count = 0;       ///< 1 or 2
  float static_friction = 0.0f;   ///< mixed coefficient
  float dynamic_friction = 0.0f;  ///< mixed coefficient
  float restitution = 0.0f;       ///< mixed coefficient
  /// False when a contact filter rejected the pair; the decision is kept while the shapes
  /// keep touching (so one-way platforms do not pop bodies through).
  bool enabled = true;
};

}  // namespace impulse2d

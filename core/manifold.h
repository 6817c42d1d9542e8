#pragma once
/// @file manifold.h
/// The narrow phase's output: up to two contact points sharing one normal.

#include "core/math.h"

#include <cstdint>

namespace impulse2d {

/// Most contact points a manifold holds (2D convex shapes touch along at most an edge).
constexpr int max_manifold_points = 2;

/// One contact point of a manifold.
struct ManifoldPoint {
  vec2 point{0.0f, 0.0f};  ///< world position, metres, midway between the two surfaces
  float depth = 0.0f;      ///< penetration, metres; positive when overlapping
  /// Which features (edges/vertices) of the two shapes made this point; equal ids on
  /// consecutive steps mean "the same point", so impulses can be carried over.
  std::uint32_t feature_id = 0;
};

/// Contact between shape A and shape B. The normal points from A to B.
struct Manifold {
  vec2 normal{0.0f, 0.0f};                      ///< unit vector from A towards B
  ManifoldPoint points[max_manifold_points];    ///< the first `point_count` are valid
  int point_count = 0;                          ///< 0 means no contact
};

/// Builds a feature id from the feature indices of the two shapes:
/// (A's feature, B's feature) packed as two 16-bit halves.
constexpr std::uint32_t make_feature_id(std::uint32_t feature_a, std::uint32_t feature_b) {
  return ((feature_a & 0xFFFFu) << 16) | (feature_b & 0xFFFFu);
}

}  // namespace impulse2d

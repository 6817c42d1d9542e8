#pragma once
/// @file collide_internal.h
/// Helpers shared by the narrow-phase files only (not part of the public API).
///
/// Feature codes: each half of a feature id (see `make_feature_id`) names one feature of one
/// shape. A vertex is its index; an edge (from vertex i to vertex i + 1) is its index tagged
/// with `edge_feature_tag`; a circle has the single feature 0. Box corners and edges are
/// numbered like `box_as_polygon`: vertices lower-left, lower-right, upper-right, upper-left;
/// edge 0 is the bottom, 1 the right, 2 the top, 3 the left.

#include "core/manifold.h"
#include "core/math.h"

#include <cstdint>

namespace impulse2d {
namespace collide_detail {

/// Marks a feature code as an edge rather than a vertex.
constexpr std::uint32_t edge_feature_tag = 0x100u;

/// Feature code of vertex `index`.
constexpr std::uint32_t vertex_feature(int index) { return static_cast<std::uint32_t>(index); }

/// Feature code of edge `index` (vertex index -> index + 1).
constexpr std::uint32_t edge_feature(int index) {
  return edge_feature_tag | static_cast<std::uint32_t>(index);
}

/// Feature code of a circle (it has one feature).
constexpr std::uint32_t circle_feature = 0u;

/// The same feature id seen with the two shapes swapped.
constexpr std::uint32_t swap_feature_id(std::uint32_t feature_id) {
  return make_feature_id(feature_id & 0xFFFFu, feature_id >> 16);
}

/// A box placed by `transform` as the narrow phase sees it: boxes never rotate, so only the
/// position is kept.
inline Transform box_transform(const Transform& transform) {
  return {transform.position, Rotation{}};
}

/// Index of the vertex after `index` in a closed outline of `count` vertices.
inline int next_vertex(int index, int count) { return index + 1 < count ? index + 1 : 0; }

}  // namespace collide_detail
}  // namespace impulse2d

#pragma once
/// @file face_search.h
/// The two face searches of the separating-axis clip (internal): the reference face along
/// whose normal the other outline is furthest out, and the incident face most anti-parallel to
/// it. Shared by sharp polygons (collide_polygons.cpp) and rounded outlines
/// (collide_rounded.cpp); any `Outline` with `vertices`, `normals` (indexable) and `count`.

#include <algorithm>

#include "core/math.h"

namespace impulse2d::collide_detail {

/// A face of the reference outline and how far the other outline's deepest vertex lies out
/// along its normal.
struct FaceSeparation {
  int face;          ///< index of the reference face
  float separation;  ///< metres between the bare outlines along the face normal (< 0: overlap)
};

/// The face of `reference` along whose normal `other` is furthest out: for each face, the
/// signed distance of other's deepest vertex; the maximum over faces (the first on a tie).
template <class Outline>
FaceSeparation max_face_separation(const Outline& reference, const Outline& other) {
  FaceSeparation best{0, 0.0f};
  for (int face = 0; face < reference.count; ++face) {
    const vec2 normal = reference.normals[face];
    const vec2 vertex = reference.vertices[face];
    float deepest = glm::dot(normal, other.vertices[0] - vertex);
    for (int j = 1; j < other.count; ++j) {
      deepest = std::min(deepest, glm::dot(normal, other.vertices[j] - vertex));
    }
    if (face == 0 || deepest > best.separation) best = {face, deepest};
  }
  return best;
}

/// The face of `incident` most anti-parallel to `reference_normal` (the first on a tie).
template <class Outline>
int incident_face(const Outline& incident, vec2 reference_normal) {
  int best_face = 0;
  float best_dot = glm::dot(reference_normal, incident.normals[0]);
  for (int face = 1; face < incident.count; ++face) {
    const float face_dot = glm::dot(reference_normal, incident.normals[face]);
    if (face_dot < best_dot) {
      best_dot = face_dot;
      best_face = face;
    }
  }
  return best_face;
}

}  // namespace impulse2d::collide_detail

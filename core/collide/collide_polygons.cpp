/// @file collide_polygons.cpp
/// Convex polygon vs convex polygon: separating axis test, reference/incident face clipping.
///
/// Feature ids: a clip point lies at one end of the contact segment; it is named by the
/// reference edge's vertex at that end and the incident edge's vertex at that end (one vertex
/// of each shape, A's in the high half). The name does not depend on whether the point was
/// clipped, so a point keeps its id while an incident vertex wanders across a side plane, and
/// swapping which shape is the reference gives the same ids for the same points.

#include "core/collide.h"
#include "core/collide/collide_internal.h"
#include "core/collide/face_search.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

using collide_detail::FaceSeparation;
using collide_detail::incident_face;
using collide_detail::max_face_separation;

using collide_detail::next_vertex;
using collide_detail::vertex_feature;

/// Keep A's face as the reference unless B's separation is clearly larger:
/// flip when sepB > sepA + relative_tolerance * |sepA| + absolute_tolerance, so B must beat A
/// by 5% of the depth (or gap) plus a millimetre. The bias keeps the choice (and so the
/// feature ids) from flickering between steps when both faces are almost equally good, e.g.
/// box on box; for overlapping pairs it is PHYSICS.md's sepB > 0.95 sepA + 0.001.
constexpr float relative_tolerance = 0.05f;
constexpr float absolute_tolerance = 0.001f;  // metres

/// A polygon's vertices and edge normals in some shared frame.
struct PolygonView {
  const vec2* vertices;
  const vec2* normals;
  int count;
};

/// A candidate contact point on the incident edge and the vertices naming it.
struct ClipPoint {
  vec2 position;
  int reference_vertex;
  int incident_vertex;
};

/// Clips the incident face of `incident` against the side planes of face `reference_face` of
/// `reference` and keeps the points behind that face. All in one frame; the manifold it
/// returns is in that frame with the normal pointing from A to B (`reference_is_b` says which
/// of A and B is the reference).
Manifold clip_incident_face(const PolygonView& reference, int reference_face,
                            const PolygonView& incident, bool reference_is_b, float margin) {
  const int reference_start = reference_face;
  const int reference_end = next_vertex(reference_face, reference.count);
  const vec2 origin = reference.vertices[reference_start];
  const vec2 normal = reference.normals[reference_face];
  // Counter-clockwise outline: the edge runs along the normal turned +90 degrees.
  const vec2 tangent = left_perpendicular(normal);
  const float reference_length = glm::dot(reference.vertices[reference_end] - origin, tangent);

  // The incident edge runs against the tangent: its end lies at the reference start's side.
  const int incident_start = incident_face(incident, normal);
  const int incident_end = next_vertex(incident_start, incident.count);
  const vec2 low_vertex = incident.vertices[incident_end];
  const vec2 high_vertex = incident.vertices[incident_start];
  const float low = glm::dot(low_vertex - origin, tangent);
  const float high = glm::dot(high_vertex - origin, tangent);
  const float span = high - low;

  // Parameters along low_vertex -> high_vertex where the side planes cut, kept on the edge.
  float low_parameter = 0.0f;
  float high_parameter = 1.0f;
  if (span > 0.0f) {
    if (low < 0.0f) low_parameter = std::min(-low / span, 1.0f);
    if (high > reference_length) high_parameter = std::max((reference_length - low) / span, 0.0f);
  }
  const vec2 incident_edge = high_vertex - low_vertex;
  ClipPoint candidates[2];
  int candidate_count = 0;
  if (low_parameter < high_parameter) {
    candidates[0] = {low_vertex + low_parameter * incident_edge, reference_start, incident_end};
    candidates[1] = {low_vertex + high_parameter * incident_edge, reference_end, incident_start};
    candidate_count = 2;
  } else if (high < 0.0f) {
    // The incident edge lies wholly before the reference start: only its nearest vertex.
    candidates[0] = {high_vertex, reference_start, incident_end};
    candidate_count = 1;
  } else {
    // Wholly past the reference end.
    candidates[0] = {low_vertex, reference_end, incident_start};
    candidate_count = 1;
  }

  Manifold manifold;
  manifold.normal = reference_is_b ? -normal : normal;
  for (int i = 0; i < candidate_count; ++i) {
    const ClipPoint& candidate = candidates[i];
    const float separation = glm::dot(candidate.position - origin, normal);
    // Strict: a point further out than the margin (or, with no margin, exactly on the
    // reference face) is not a contact.
    if (!(separation < margin)) continue;
    ManifoldPoint& point = manifold.points[manifold.point_count++];
    point.depth = -separation;
    // Midway between the incident vertex and its projection on the reference face.
    point.point = candidate.position - 0.5f * separation * normal;
    const std::uint32_t reference_feature = vertex_feature(candidate.reference_vertex);
    const std::uint32_t incident_feature = vertex_feature(candidate.incident_vertex);
    point.feature_id = reference_is_b ? make_feature_id(incident_feature, reference_feature)
                                      : make_feature_id(reference_feature, incident_feature);
  }
  return manifold;
}

}  // namespace

Manifold collide_polygons(const Polygon& a, const Transform& xa, const Polygon& b,
                          const Transform& xb, float margin) {
  // Work in A's frame. Composing the relative rotation first (rather than going through world
  // space) keeps B's edges exactly parallel to A's when both have the same angle.
  const Rotation relative_rotation{
      xa.rotation.cosine * xb.rotation.cosine + xa.rotation.sine * xb.rotation.sine,
      xa.rotation.cosine * xb.rotation.sine - xa.rotation.sine * xb.rotation.cosine};
  const Transform relative{xa.rotation.inverse_rotate(xb.position - xa.position),
                           relative_rotation};
  vec2 b_vertices[max_polygon_vertices];
  vec2 b_normals[max_polygon_vertices];
  for (int i = 0; i < b.count; ++i) {
    b_vertices[i] = relative.apply(b.vertices[i]);
    b_normals[i] = relative.rotation.rotate(b.normals[i]);
  }
  const PolygonView view_a{a.vertices.data(), a.normals.data(), a.count};
  const PolygonView view_b{b_vertices, b_normals, b.count};

  // Strict: polygons further apart than the margin (or, with no margin, that only touch)
  // make no contact.
  const FaceSeparation separation_a = max_face_separation(view_a, view_b);
  if (!(separation_a.separation < margin)) return Manifold{};
  const FaceSeparation separation_b = max_face_separation(view_b, view_a);
  if (!(separation_b.separation < margin)) return Manifold{};

  const float sep_a = separation_a.separation;
  const bool reference_is_b = separation_b.separation >
                              sep_a + relative_tolerance * std::fabs(sep_a) + absolute_tolerance;
  Manifold manifold =
      reference_is_b ? clip_incident_face(view_b, separation_b.face, view_a, true, margin)
                     : clip_incident_face(view_a, separation_a.face, view_b, false, margin);

  manifold.normal = xa.rotation.rotate(manifold.normal);
  for (int i = 0; i < manifold.point_count; ++i) {
    manifold.points[i].point = xa.apply(manifold.points[i].point);
  }
  return manifold;
}

}  // namespace impulse2d

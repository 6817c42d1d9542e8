/// @file collide_rounded.cpp
/// Rounded convex outlines: a polygon with a rounding radius, a capsule (a 2-vertex outline
/// with the capsule's radius, as Box2D v3 treats it), a segment (a capsule of radius 0) and a
/// box (4 vertices, radius 0), against each other and against a circle. One routine serves
/// every such pair: the separating axis test on the bare outlines, reference/incident face
/// clipping with the radii added to the depths, and, when the outlines are apart and nearest
/// at a corner, one point along the line between the nearest points (the circle's normal).
///
/// Feature ids follow collide_polygons.cpp: a clip point is named by the reference edge's
/// vertex and the incident edge's vertex at its end of the contact segment (A's in the high
/// half); a corner point by the nearest vertex (or edge) of each outline.

#include "core/collide.h"
#include "core/collide/collide_internal.h"
#include "core/collide/face_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse2d {

namespace {

using collide_detail::FaceSeparation;
using collide_detail::incident_face;
using collide_detail::max_face_separation;

using collide_detail::edge_feature;
using collide_detail::next_vertex;
using collide_detail::vertex_feature;

/// Reference-face bias of collide_polygons.cpp: B's face is the reference only when its
/// separation beats A's by 5% plus a millimetre, so the choice does not flicker.
constexpr float relative_tolerance = 0.05f;
constexpr float absolute_tolerance = 0.001f;  // metres

/// Outlines further apart than this (metres) are treated as disjoint: the nearest points of
/// their edges are then far enough apart to give a well-defined direction (Box2D v3 uses a
/// tenth of its 5 mm linear slop).
constexpr float corner_tolerance = 0.0005f;

/// A convex outline grown by a radius: 2 vertices for a capsule or segment (edge 0 runs
/// vertex 0 -> 1 with normal n, edge 1 back with -n), 3..8 for a polygon, 4 for a box.
struct RoundedOutline {
  vec2 vertices[max_polygon_vertices];
  vec2 normals[max_polygon_vertices];
  int count = 0;
  float radius = 0.0f;  ///< metres
};

RoundedOutline two_vertex_outline(vec2 first, vec2 second, float radius) {
  RoundedOutline outline;
  outline.count = 2;
  outline.vertices[0] = first;
  outline.vertices[1] = second;
  outline.normals[0] = glm::normalize(right_perpendicular(second - first));
  outline.normals[1] = -outline.normals[0];
  outline.radius = radius;
  return outline;
}

/// The outline of a box, polygon, capsule or segment in its body's frame, and the transform
/// the narrow phase places it with (a box's ignores the rotation).
RoundedOutline outline_of(const Shape& shape, const Transform& transform, Transform* placed) {
  *placed = transform;
  RoundedOutline outline;
  switch (shape.type()) {
    case ShapeType::Box: {
      const Polygon polygon = box_as_polygon(shape.box());
      outline.count = 4;
      std::copy(polygon.vertices.begin(), polygon.vertices.begin() + 4, outline.vertices);
      std::copy(polygon.normals.begin(), polygon.normals.begin() + 4, outline.normals);
      *placed = collide_detail::box_transform(transform);
      return outline;
    }
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      outline.count = polygon.count;
      std::copy(polygon.vertices.begin(), polygon.vertices.begin() + polygon.count, outline.vertices);
      std::copy(polygon.normals.begin(), polygon.normals.begin() + polygon.count, outline.normals);
      outline.radius = polygon.rounding;
      return outline;
    }
    case ShapeType::Capsule:
      return two_vertex_outline(shape.capsule().center1, shape.capsule().center2,
                                shape.capsule().radius);
    case ShapeType::Segment:
      return two_vertex_outline(shape.segment().point1, shape.segment().point2, 0.0f);
    case ShapeType::Circle:
      break;
  }
  // A circle is not an outline here: collide_rounded_circle takes it as the point it is.
  outline.count = 1;
  outline.radius = shape.circle().radius;
  return outline;
}

/// The nearest points of segments p0 -> p1 and q0 -> q1: their fractions along each.
struct NearestPoints {
  float fraction_p;
  float fraction_q;
  float distance_squared;
};

NearestPoints nearest_points(vec2 p0, vec2 p1, vec2 q0, vec2 q1) {
  const vec2 d1 = p1 - p0;
  const vec2 d2 = q1 - q0;
  const vec2 r = p0 - q0;
  const float dd1 = glm::dot(d1, d1);
  const float dd2 = glm::dot(d2, d2);
  const float rd1 = glm::dot(r, d1);
  const float rd2 = glm::dot(r, d2);
  const float d12 = glm::dot(d1, d2);
  const float denominator = dd1 * dd2 - d12 * d12;
  // Nearest point on the infinite lines, clamped to the first segment, then the second's
  // nearest point to it, clamped, and the first's again (Ericson, Real-Time Collision
  // Detection 5.1.9); both lengths are > 0 here (outline edges).
  float s = denominator > 0.0f ? std::clamp((d12 * rd2 - rd1 * dd2) / denominator, 0.0f, 1.0f) : 0.0f;
  float t = (rd2 + s * d12) / dd2;
  if (t < 0.0f) {
    t = 0.0f;
    s = std::clamp(-rd1 / dd1, 0.0f, 1.0f);
  } else if (t > 1.0f) {
    t = 1.0f;
    s = std::clamp((d12 - rd1) / dd1, 0.0f, 1.0f);
  }
  return {s, t, length_squared((p0 + s * d1) - (q0 + t * d2))};
}

/// Feature code of the point at `fraction` along edge `face` (start vertex, end vertex, or
/// the edge itself).
std::uint32_t feature_at(float fraction, int face, int count) {
  if (fraction == 0.0f) return vertex_feature(face);
  if (fraction == 1.0f) return vertex_feature(next_vertex(face, count));
  return edge_feature(face);
}

/// Clips the incident face against the reference face's side planes; keeps the points whose
/// gap (along the reference normal, less both radii) is below `margin`. When the incident face
/// lies wholly beside the reference face, only its vertex nearest to it is a candidate and
/// `beside` is set (the corner case then looks for a better point).
Manifold clip_faces(const RoundedOutline& reference, int reference_face,
                    const RoundedOutline& incident, int incident_start, bool reference_is_b,
                    float margin, bool* beside) {
  Manifold manifold;
  const int reference_start = reference_face;
  const int reference_end = next_vertex(reference_face, reference.count);
  const vec2 origin = reference.vertices[reference_start];
  const vec2 normal = reference.normals[reference_face];
  const vec2 tangent = left_perpendicular(normal);
  const float reference_length = glm::dot(reference.vertices[reference_end] - origin, tangent);

  // The incident edge runs against the tangent: its end lies at the reference start's side.
  const int incident_end = next_vertex(incident_start, incident.count);
  const vec2 low_vertex = incident.vertices[incident_end];
  const vec2 high_vertex = incident.vertices[incident_start];
  const float low = glm::dot(low_vertex - origin, tangent);
  const float high = glm::dot(high_vertex - origin, tangent);
  *beside = high < 0.0f || low > reference_length;
  const float span = high - low;
  float low_parameter = 0.0f;
  float high_parameter = 1.0f;
  if (span > 0.0f) {
    if (low < 0.0f) low_parameter = std::min(-low / span, 1.0f);
    if (high > reference_length) high_parameter = std::max((reference_length - low) / span, 0.0f);
  }
  const vec2 incident_edge = high_vertex - low_vertex;
  struct Candidate {
    vec2 position;
    int reference_vertex;
    int incident_vertex;
  };
  Candidate candidates[2] = {
      {low_vertex + low_parameter * incident_edge, reference_start, incident_end},
      {low_vertex + high_parameter * incident_edge, reference_end, incident_start}};
  int candidate_count = 2;
  if (high < 0.0f) {
    candidates[0] = {high_vertex, reference_start, incident_end};  // wholly before the start
    candidate_count = 1;
  } else if (low > reference_length) {
    candidates[0] = {low_vertex, reference_end, incident_start};  // wholly past the end
    candidate_count = 1;
  }
  const float radius = reference.radius + incident.radius;
  manifold.normal = reference_is_b ? -normal : normal;
  for (int i = 0; i < candidate_count; ++i) {
    const Candidate& candidate = candidates[i];
    const float separation = glm::dot(candidate.position - origin, normal);
    if (!(separation - radius < margin)) continue;
    ManifoldPoint& point = manifold.points[manifold.point_count++];
    point.depth = radius - separation;
    // Midway between the incident surface and the reference surface.
    point.point = candidate.position +
                  0.5f * (reference.radius - incident.radius - separation) * normal;
    const std::uint32_t reference_feature = vertex_feature(candidate.reference_vertex);
    const std::uint32_t incident_feature = vertex_feature(candidate.incident_vertex);
    point.feature_id = reference_is_b ? make_feature_id(incident_feature, reference_feature)
                                      : make_feature_id(reference_feature, incident_feature);
  }
  return manifold;
}

/// Places the outline given in B's frame into A's frame (`relative` = A^-1 B).
RoundedOutline moved(const RoundedOutline& outline, const Transform& relative) {
  RoundedOutline result = outline;
  for (int i = 0; i < outline.count; ++i) {
    result.vertices[i] = relative.apply(outline.vertices[i]);
    result.normals[i] = relative.rotation.rotate(outline.normals[i]);
  }
  return result;
}

/// B's pose in A's frame. Composing the relative rotation first keeps B's edges exactly
/// parallel to A's when both have the same angle.
Transform relative_transform(const Transform& xa, const Transform& xb) {
  const Rotation relative_rotation{
      xa.rotation.cosine * xb.rotation.cosine + xa.rotation.sine * xb.rotation.sine,
      xa.rotation.cosine * xb.rotation.sine - xa.rotation.sine * xb.rotation.cosine};
  return Transform{xa.rotation.inverse_rotate(xb.position - xa.position), relative_rotation};
}

}  // namespace

Manifold collide_rounded(const Shape& a, const Transform& xa, const Shape& b, const Transform& xb,
                         float margin) {
  Transform placed_a;
  Transform placed_b;
  const RoundedOutline outline_a = outline_of(a, xa, &placed_a);
  const RoundedOutline local_b = outline_of(b, xb, &placed_b);
  const RoundedOutline outline_b = moved(local_b, relative_transform(placed_a, placed_b));
  const float radius = outline_a.radius + outline_b.radius;
  const float reach = margin + radius;

  const FaceSeparation separation_a = max_face_separation(outline_a, outline_b);
  if (!(separation_a.separation < reach)) return Manifold{};
  const FaceSeparation separation_b = max_face_separation(outline_b, outline_a);
  if (!(separation_b.separation < reach)) return Manifold{};

  const float sep_a = separation_a.separation;
  const bool reference_is_b = separation_b.separation >
                              sep_a + relative_tolerance * std::fabs(sep_a) + absolute_tolerance;
  const RoundedOutline& reference = reference_is_b ? outline_b : outline_a;
  const RoundedOutline& incident = reference_is_b ? outline_a : outline_b;
  const int reference_face = reference_is_b ? separation_b.face : separation_a.face;
  const int incident_start = incident_face(incident, reference.normals[reference_face]);
  bool beside = false;
  Manifold manifold = clip_faces(reference, reference_face, incident, incident_start,
                                 reference_is_b, margin, &beside);

  const float separation = std::max(separation_a.separation, separation_b.separation);
  if (separation > corner_tolerance || (beside && separation > -corner_tolerance)) {
    // The outlines are apart (or just touch with the incident face wholly beside the reference
    // face: two capsules end to end, whose separating axis runs along them, no face normal of
    // either).
    // Where the faces' nearest points are closer than the clipped points say (a corner against
    // a corner or beside a face), the rounded surfaces meet along the line between those
    // nearest points: one point with the circle's normal there.
    // The nearest pair of faces of the two cores, over every pair (at most 8 x 8): the faces
    // the clip chose need not be it (a needle-thin outline has two faces about equally
    // anti-parallel to the reference normal, far apart along it).
    int face_a = 0;
    int face_b = 0;
    NearestPoints nearest{0.0f, 0.0f, std::numeric_limits<float>::max()};
    for (int i = 0; i < outline_a.count; ++i) {
      for (int j = 0; j < outline_b.count; ++j) {
        const NearestPoints candidate = nearest_points(
            outline_a.vertices[i], outline_a.vertices[next_vertex(i, outline_a.count)],
            outline_b.vertices[j], outline_b.vertices[next_vertex(j, outline_b.count)]);
        if (candidate.distance_squared < nearest.distance_squared) {
          nearest = candidate;
          face_a = i;
          face_b = j;
        }
      }
    }
    const vec2 a0 = outline_a.vertices[face_a];
    const vec2 a1 = outline_a.vertices[next_vertex(face_a, outline_a.count)];
    const vec2 b0 = outline_b.vertices[face_b];
    const vec2 b1 = outline_b.vertices[next_vertex(face_b, outline_b.count)];
    const float distance = std::sqrt(nearest.distance_squared);
    float clipped_gap = std::numeric_limits<float>::max();
    for (int i = 0; i < manifold.point_count; ++i) {
      clipped_gap = std::min(clipped_gap, -manifold.points[i].depth);
    }
    // A face beside the other is measured by its nearest points (the clipped vertex's gap
    // along the reference normal understates it); cores that meet (distance 0) keep the
    // clipped point: there is no direction between them.
    if ((beside || distance - radius + corner_tolerance < clipped_gap) && distance > corner_tolerance) {
      manifold = Manifold{};
      if (!(distance - radius < margin)) return manifold;
      const vec2 on_a = a0 + nearest.fraction_p * (a1 - a0);
      const vec2 on_b = b0 + nearest.fraction_q * (b1 - b0);
      const vec2 normal = (on_b - on_a) / distance;
      manifold.normal = normal;
      manifold.point_count = 1;
      manifold.points[0].depth = radius - distance;
      manifold.points[0].point =
          0.5f * ((on_a + outline_a.radius * normal) + (on_b - outline_b.radius * normal));
      manifold.points[0].feature_id =
          make_feature_id(feature_at(nearest.fraction_p, face_a, outline_a.count),
                          feature_at(nearest.fraction_q, face_b, outline_b.count));
    }
  }

  manifold.normal = placed_a.rotation.rotate(manifold.normal);
  for (int i = 0; i < manifold.point_count; ++i) {
    manifold.points[i].point = placed_a.apply(manifold.points[i].point);
  }
  return manifold;
}

Manifold collide_rounded_circle(const Shape& a, const Transform& xa, const Circle& b,
                                const Transform& xb, float margin) {
  Transform placed_a;
  const RoundedOutline outline = outline_of(a, xa, &placed_a);
  const vec2 centre = placed_a.apply_inverse(xb.position);
  const float radius = outline.radius + b.radius;

  // The face the centre is furthest outside of (or least inside of).
  int face = 0;
  float separation = glm::dot(outline.normals[0], centre - outline.vertices[0]);
  for (int i = 1; i < outline.count; ++i) {
    const float face_separation = glm::dot(outline.normals[i], centre - outline.vertices[i]);
    if (face_separation > separation) {
      separation = face_separation;
      face = i;
    }
  }
  const float reach = radius + margin;
  if (!(separation < reach)) return Manifold{};

  const vec2 start = outline.vertices[face];
  const vec2 end = outline.vertices[next_vertex(face, outline.count)];
  vec2 normal = outline.normals[face];
  vec2 nearest = centre - separation * normal;  // projection of the centre on the face
  std::uint32_t feature_a = edge_feature(face);
  if (separation >= 0.0f) {
    // Outside (or on the line of a segment): the face's start vertex region, its end vertex
    // region, or the face.
    const bool before_start = glm::dot(centre - start, end - start) <= 0.0f;
    const bool after_end = glm::dot(centre - end, start - end) <= 0.0f;
    if (before_start || after_end) {
      const vec2 vertex = before_start ? start : end;
      const vec2 offset = centre - vertex;
      const float distance_squared = length_squared(offset);
      if (!(reach * reach > distance_squared)) return Manifold{};
      // A centre exactly on the vertex keeps the face normal.
      if (distance_squared > 0.0f) normal = offset / std::sqrt(distance_squared);
      nearest = vertex;
      feature_a = vertex_feature(before_start ? face : next_vertex(face, outline.count));
    }
  }
  // Otherwise the centre is inside the outline: out through the face of greatest separation.

  Manifold manifold;
  manifold.normal = placed_a.rotation.rotate(normal);
  manifold.point_count = 1;
  manifold.points[0].depth = radius - glm::dot(centre - nearest, normal);
  const vec2 surface_a = nearest + outline.radius * normal;
  const vec2 surface_b = centre - b.radius * normal;
  manifold.points[0].point = placed_a.apply(0.5f * (surface_a + surface_b));
  manifold.points[0].feature_id = make_feature_id(feature_a, collide_detail::circle_feature);
  return manifold;
}

}  // namespace impulse2d

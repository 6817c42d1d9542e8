/// @file collide_chain_link.cpp
/// A chain link (a one-sided segment with ghost vertices, see `Segment`) against a circle,
/// box, polygon or capsule.
///
/// The link is collided as the plain segment it is, then the result is kept, dropped or
/// replaced so that a chain acts as one surface:
/// - a shape whose centre is behind the link (right of point1 -> point2) does not touch it;
/// - a manifold along the link's front normal is kept;
/// - any other normal comes from one of the link's ends. At an end where the chain bends away
///   from the front side (a convex corner) the corner owns the normals between the two links'
///   normals: the link that starts at the corner keeps them, the link that ends there drops
///   them (its neighbour reports them), and a normal beyond the neighbour's is the neighbour's
///   face. At a flat or concave join (and wherever the normal points behind the link) there
///   is no corner to push from: the manifold is rebuilt along the front normal, the other
///   shape's nearest edge (or point) clipped to the link's extent. That is what removes the
///   bump a body sliding across a seam of tiled ground feels ("ghost collisions").
/// - an open chain's end (ghost equal to the end point) is a free corner: kept as collided.

#include "core/collide.h"
#include "core/collide/collide_internal.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

using collide_detail::edge_feature;
using collide_detail::next_vertex;
using collide_detail::vertex_feature;

/// |sin| of the angle below which two links count as one straight line (about 0.03 degrees):
/// float rounding of chain points listed on a line gives far less, a modelled bend far more.
constexpr float straight_tolerance = 5e-4f;

/// Slack (in |sin|) of the test that a normal lies within a corner's range of normals.
constexpr float cone_tolerance = 1e-5f;

/// Feature code (of the other shape) of a point where the link's end `end` (0: point1, 1:
/// point2) cut the other shape's incident edge `edge`.
constexpr std::uint32_t clip_feature(int end, int edge) {
  return 0x200u | (static_cast<std::uint32_t>(end) << 4) | static_cast<std::uint32_t>(edge);
}

/// The other shape as a convex outline grown by a radius, in world coordinates.
struct WorldOutline {
  vec2 vertices[max_polygon_vertices];
  vec2 normals[max_polygon_vertices];  ///< of edge i -> i + 1 (count >= 3 only)
  int count = 0;
  float radius = 0.0f;  ///< metres
};

WorldOutline world_outline(const Shape& shape, const Transform& transform) {
  WorldOutline outline;
  switch (shape.type()) {
    case ShapeType::Circle:
      outline.count = 1;
      outline.vertices[0] = transform.position;
      outline.radius = shape.circle().radius;
      break;
    case ShapeType::Box: {
      const Polygon polygon = box_as_polygon(shape.box());
      outline.count = 4;
      for (int i = 0; i < 4; ++i) {
        outline.vertices[i] = transform.position + polygon.vertices[i];
        outline.normals[i] = polygon.normals[i];
      }
      break;
    }
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      outline.count = polygon.count;
      for (int i = 0; i < polygon.count; ++i) {
        outline.vertices[i] = transform.apply(polygon.vertices[i]);
        outline.normals[i] = transform.rotation.rotate(polygon.normals[i]);
      }
      outline.radius = polygon.rounding;
      break;
    }
    case ShapeType::Capsule:
      outline.count = 2;
      outline.vertices[0] = transform.apply(shape.capsule().center1);
      outline.vertices[1] = transform.apply(shape.capsule().center2);
      outline.radius = shape.capsule().radius;
      break;
    case ShapeType::Segment:
      break;  // never reached: links do not collide with segments
  }
  return outline;
}

/// The manifold along the link's front normal `normal`: the other shape's feature facing the
/// link (a polygon's edge most against the normal, a capsule's core, a circle's centre) clipped
/// to the link's extent, each point kept when its gap is below `margin`.
Manifold face_manifold(vec2 point1, vec2 point2, vec2 normal, const WorldOutline& other,
                       float margin, const bool straight[2]) {
  int first = 0;
  int second = 0;
  if (other.count == 2) {
    second = 1;
  } else if (other.count > 2) {
    float most_against = glm::dot(other.normals[0], normal);
    for (int i = 1; i < other.count; ++i) {
      const float along = glm::dot(other.normals[i], normal);
      if (along < most_against) {
        most_against = along;
        first = i;
      }
    }
    second = next_vertex(first, other.count);
  }
  const vec2 edge = point2 - point1;
  const float length = glm::length(edge);
  const vec2 direction = edge / length;
  // The incident feature as the fractions t (metres along the link from point1) of its ends.
  const vec2 v[2] = {other.vertices[first], other.vertices[second]};
  float t[2] = {glm::dot(v[0] - point1, direction), glm::dot(v[1] - point1, direction)};
  std::uint32_t feature[2] = {vertex_feature(first), vertex_feature(second)};
  Manifold manifold;
  manifold.normal = normal;
  const int ends = first == second ? 1 : 2;
  vec2 clipped[2] = {v[0], v[1]};
  for (int i = 0; i < ends; ++i) {
    const float limit = t[i] < 0.0f ? 0.0f : (t[i] > length ? length : t[i]);
    if (limit == t[i]) continue;
    if (ends == 1) return manifold;  // a point beyond the link's end: its neighbour's
    const int j = 1 - i;
    if ((t[j] < 0.0f && t[i] < 0.0f) || (t[j] > length && t[i] > length)) return manifold;
    if (straight[limit == 0.0f ? 0 : 1]) {
      feature[i] = 0xFFFFu;  // the neighbour's point
      continue;
    }
    const float s = (limit - t[j]) / (t[i] - t[j]);
    clipped[i] = v[j] + s * (v[i] - v[j]);
    feature[i] = clip_feature(limit == 0.0f ? 0 : 1, first);
  }
  for (int i = 0; i < ends; ++i) {
    if (feature[i] == 0xFFFFu) continue;
    const float height = glm::dot(clipped[i] - point1, normal);
    const float gap = height - other.radius;
    if (!(gap <= margin)) continue;
    ManifoldPoint& out = manifold.points[manifold.point_count++];
    out.point = clipped[i] - 0.5f * (height + other.radius) * normal;
    out.depth = -gap;
    out.feature_id = make_feature_id(edge_feature(0), feature[i]);
  }
  return manifold;
}

/// How a chain goes on past a link's end.
enum class Join {
  Free,      ///< an open chain's end: a corner free on every side
  Convex,    ///< bends away from the front side: the corner pushes along its own normals
  Straight,  ///< on in a straight line: one flat surface
  Concave,   ///< bends towards the front side: no corner to push from
};

/// The join from direction `incoming` to direction `outgoing` (chain edges, metres).
Join join_between(vec2 incoming, vec2 outgoing, bool free) {
  if (free) return Join::Free;
  const float bend = cross(incoming, outgoing);
  const float straight = straight_tolerance * glm::length(incoming) * glm::length(outgoing);
  if (bend < -straight) return Join::Convex;
  return bend > straight ? Join::Concave : Join::Straight;
}

/// True when unit `normal` lies between unit normals `from` and `to` of a convex corner (from
/// `from` turning clockwise to `to`).
bool within_corner(vec2 from, vec2 to, vec2 normal) {
  return cross(from, normal) <= cone_tolerance && cross(normal, to) <= cone_tolerance;
}

}  // namespace

Manifold collide_chain_link(const Shape& link, const Transform& xa, const Shape& other,
                            const Transform& xb, float margin) {
  const Segment& segment = link.segment();
  if (other.type() == ShapeType::Segment) return Manifold{};  // neither can be dynamic
  const vec2 point1 = xa.apply(segment.point1);
  const vec2 point2 = xa.apply(segment.point2);
  const vec2 edge = point2 - point1;
  const vec2 front = glm::normalize(left_perpendicular(edge));
  if (glm::dot(xb.position - point1, front) < 0.0f) return Manifold{};  // behind the link

  // How the chain goes on past each end.
  const vec2 before = point1 - xa.apply(segment.ghost1);
  const vec2 after = xa.apply(segment.ghost2) - point2;
  const Join start = join_between(before, edge, segment.ghost1 == segment.point1);
  const Join finish = join_between(edge, after, segment.ghost2 == segment.point2);
  const bool straight[2] = {start == Join::Straight, finish == Join::Straight};
  const WorldOutline outline = world_outline(other, xb);

  Segment two_sided = segment;
  two_sided.one_sided = false;
  const Manifold collided = collide(Shape(two_sided), xa, other, xb, margin);
  if (collided.point_count == 0) return collided;
  const vec2 normal = collided.normal;
  const float facing = glm::dot(normal, front);
  if (facing >= 1.0f - cone_tolerance || facing <= 0.0f) {
    return face_manifold(point1, point2, front, outline, margin, straight);
  }
  if (glm::dot(normal, edge) < 0.0f) {
    // Tilted back towards point1: the corner with the previous link, this link's to report.
    if (start == Join::Free) return collided;
    if (start == Join::Convex) {
      const vec2 previous_front = glm::normalize(left_perpendicular(before));
      return within_corner(previous_front, front, normal) ? collided : Manifold{};
    }
  } else {
    // Tilted on towards point2: the corner with the next link, the next link's to report.
    if (finish == Join::Free) return collided;
    if (finish == Join::Convex) return Manifold{};
  }
  return face_manifold(point1, point2, front, outline, margin, straight);
}

}  // namespace impulse2d

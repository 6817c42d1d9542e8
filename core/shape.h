#pragma once
/// @file shape.h
/// Collision shapes: circle, axis-aligned box, convex polygon (optionally rounded), capsule and
/// segment, validated on creation. Every shape is stored in body-local coordinates with the
/// body origin at its centroid (a segment's: its midpoint).

#include "core/math.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d {

/// The kinds of shape; the narrow phase's jump table is indexed by these.
enum class ShapeType : std::uint8_t { Circle = 0, Box = 1, Polygon = 2, Capsule = 3, Segment = 4 };

/// Number of shape kinds (size of each dimension of the collision jump table).
constexpr int shape_type_count = 5;

/// Largest number of vertices a convex polygon may have.
constexpr int max_polygon_vertices = 8;

/// A solid disc centred on the body origin.
struct Circle {
  float radius = 0.5f;  ///< metres, > 0
};

/// An axis-aligned box centred on the body origin. It never rotates: a body with this shape
/// has its rotation fixed, which lets the narrow phase use the cheap AABB tests.
struct Box {
  vec2 half_extents{0.5f, 0.5f};  ///< half width and half height, metres, > 0
};

/// A convex polygon, counter-clockwise, with its centroid at the body origin. With a rounding
/// radius r > 0 the solid is the polygon swollen by r (every point within r of it): flat edges
/// pushed out by r, corners turned into arcs of radius r about the vertices.
struct Polygon {
  int count = 0;                                     ///< number of vertices, 3..8
  std::array<vec2, max_polygon_vertices> vertices{};  ///< local vertices, metres, CCW
  std::array<vec2, max_polygon_vertices> normals{};   ///< outward unit normal of edge i -> i+1
  /// Distance (m) of the farthest vertex from the origin, kept by `make_polygon` and
  /// `make_oriented_box` so the step need not recompute it; negative (unknown) for a polygon
  /// filled in by hand, whose radius `polygon_radius` then computes from the vertices. Edit
  /// the vertices of a made polygon only through `make_polygon` (or set this back to -1).
  float radius = -1.0f;
  /// Rounding radius (m, >= 0) added all round the outline above; 0 is a sharp polygon.
  float rounding = 0.0f;
};

/// A capsule: every point within `radius` of the segment from `center1` to `center2` (a
/// rectangle with a half disc on each end), its centroid (the midpoint) at the body origin.
struct Capsule {
  vec2 center1{0.0f, -0.5f};  ///< centre of the first end cap, metres, body-local
  vec2 center2{0.0f, 0.5f};   ///< centre of the second end cap, metres, body-local, != center1
  float radius = 0.25f;       ///< metres, > 0
};

/// A line segment with no thickness and no area (so no mass): for static and kinematic bodies
/// (level geometry, moving platforms). Stored with its midpoint at the body origin.
///
/// A link of a chain (`make_chain`) is one-sided: it collides only with shapes whose centre is
/// in front of it, on the left of the direction point1 -> point2 (a ground line listed left to
/// right faces up), and it knows its neighbours' far points (ghost vertices) so that a body
/// crossing from one link to the next feels one smooth surface (no "ghost collision" at the
/// seam, as Box2D's chain segments).
struct Segment {
  vec2 point1{-0.5f, 0.0f};  ///< one end, metres, body-local
  vec2 point2{0.5f, 0.0f};   ///< the other end, metres, body-local, != point1
  bool one_sided = false;    ///< a chain link: front side only, smoothed by the ghosts
  /// The previous chain point (metres, body-local); equal to `point1` at an open chain's start,
  /// where the end is a free corner. Read only when `one_sided`.
  vec2 ghost1{0.0f, 0.0f};
  /// The next chain point (metres, body-local); equal to `point2` at an open chain's end.
  vec2 ghost2{0.0f, 0.0f};
};

/// A shape of one kind: a tagged union (the kind, then the one kind's data), 144 bytes. Build
/// it with `make_circle`, `make_box`, `make_polygon`, `make_oriented_box`, `make_capsule` or
/// `make_segment`, which validate their input (a kind's struct converts too, unvalidated until
/// `World::create_body`).
///
/// Adding a kind: its struct above and its `ShapeType` (before `shape_type_count`); here a
/// member of the union, a constructor and an accessor; its case in each `switch (type())`
/// (shape.h, shape.cpp, world.cpp, world_draw.cpp, collide/continuous.cpp,
/// collide/speculative_meeting.cpp; -Wswitch names any left out); and its row and column of
/// collide functions in collide/collision_table.cpp.
class Shape {
 public:
  /// A circle of radius 0.5 m.
  Shape() : Shape(Circle{}) {}
  /// A circle shape.
  Shape(const Circle& circle) : type_(ShapeType::Circle), circle_(circle) {}
  /// An axis-aligned box shape.
  Shape(const Box& box) : type_(ShapeType::Box), box_(box) {}
  /// A convex polygon shape.
  Shape(const Polygon& polygon) : type_(ShapeType::Polygon), polygon_(polygon) {}
  /// A capsule shape.
  Shape(const Capsule& capsule) : type_(ShapeType::Capsule), capsule_(capsule) {}
  /// A segment shape.
  Shape(const Segment& segment) : type_(ShapeType::Segment), segment_(segment) {}

  /// Which kind this shape is: the accessor of that kind alone may be called.
  ShapeType type() const { return type_; }
  /// The circle; only when `type() == ShapeType::Circle`.
  const Circle& circle() const {
    assert(type_ == ShapeType::Circle);
    return circle_;
  }
  /// The box; only when `type() == ShapeType::Box`.
  const Box& box() const {
    assert(type_ == ShapeType::Box);
    return box_;
  }
  /// The polygon; only when `type() == ShapeType::Polygon`.
  const Polygon& polygon() const {
    assert(type_ == ShapeType::Polygon);
    return polygon_;
  }
  /// The capsule; only when `type() == ShapeType::Capsule`.
  const Capsule& capsule() const {
    assert(type_ == ShapeType::Capsule);
    return capsule_;
  }
  /// The segment; only when `type() == ShapeType::Segment`.
  const Segment& segment() const {
    assert(type_ == ShapeType::Segment);
    return segment_;
  }

 private:
  ShapeType type_;
  union {
    Circle circle_;
    Box box_;
    Polygon polygon_;
    Capsule capsule_;
    Segment segment_;
  };
};

/// Checks a shape built by hand (or converted from a kind's struct) as `World::create_body`
/// does: throws `Error` prefixed by `caller` naming what is wrong (a radius <= 0, too few
/// vertices, equal points, a non-finite value).
void validate_shape(const Shape& shape, const std::string& caller);

/// A circle of the given radius (metres). Throws `Error` unless 0 < radius < inf.
Shape make_circle(float radius);

/// An axis-aligned box of the given half extents (metres). Throws `Error` unless both are
/// finite and positive.
Shape make_box(vec2 half_extents);

/// A convex polygon from 3..8 vertices in counter-clockwise order (metres). The vertices are
/// shifted so that the centroid is at the body origin; `centroid_out`, when given, receives
/// the centroid of the input so a caller can place the body there. Throws `Error` for too few
/// or too many vertices, non-finite values, a clockwise order, a non-convex or
/// self-overlapping outline, repeated points, or a degenerate (near zero) area.
Shape make_polygon(const vec2* vertices, int count, vec2* centroid_out = nullptr);

/// A rounded convex polygon: `make_polygon`'s outline (same checks, same re-centring) swollen
/// by `rounding` metres all round. Throws `Error` as `make_polygon` does, or unless
/// 0 <= rounding < inf. Rounding 0 gives exactly `make_polygon`'s shape.
Shape make_rounded_polygon(const vec2* vertices, int count, float rounding,
                           vec2* centroid_out = nullptr);

/// A capsule of the given end-cap centres and radius (metres), shifted so that its centroid
/// (the midpoint of the centres) is at the body origin; `centroid_out`, when given, receives
/// that midpoint in the input coordinates. Throws `Error` for non-finite input, radius <= 0, or
/// centres closer than 64 float epsilons of their size (a circle is the shape for that).
Shape make_capsule(vec2 center1, vec2 center2, float radius, vec2* centroid_out = nullptr);

/// A segment between two points (metres), shifted so that its midpoint is at the body origin;
/// `centroid_out`, when given, receives the midpoint in the input coordinates. Throws `Error`
/// for non-finite points or a (near) zero length. A segment has no mass: only a static or
/// kinematic body may have one.
Shape make_segment(vec2 point1, vec2 point2, vec2* centroid_out = nullptr);

/// One link of a chain: a one-sided segment shape (midpoint at its body origin) and where that
/// body goes (the midpoint, in the coordinates of the chain's points).
struct ChainLink {
  Shape shape;                 ///< a `Segment` with `one_sided` and its ghosts set
  vec2 position{0.0f, 0.0f};   ///< the link's midpoint, metres
};

/// The links of a chain through `count` points (metres): one one-sided segment per pair of
/// consecutive points, and with `loop` one more from the last point back to the first. Bodies
/// collide with the side on the left of the direction of the points (a ground line listed
/// left to right is solid below; a loop listed clockwise is solid inside, counter-clockwise a
/// track ridden inside). Throws `Error` naming the point for fewer than 2 points (3 for a
/// loop), more than 100000, non-finite points, a point equal to the one before it, or a loop
/// whose last point repeats the first (a loop closes itself).
std::vector<ChainLink> make_chain(const vec2* points, int count, bool loop);

/// Distance (m) of the polygon's farthest vertex from its centre, computed from the vertices
/// (what `Polygon::radius` caches).
float farthest_vertex_distance(const Polygon& polygon);

/// Distance (m) of the polygon's farthest vertex from its centre (the body's centre of mass):
/// `polygon.radius` when known, else computed from the vertices.
inline float polygon_radius(const Polygon& polygon) {
  return polygon.radius >= 0.0f ? polygon.radius : farthest_vertex_distance(polygon);
}

/// Farthest distance (m) of the shape's surface from its centre (the body's centre of mass).
inline float shape_extent(const Shape& shape) {
  switch (shape.type()) {
    case ShapeType::Circle: return shape.circle().radius;
    case ShapeType::Box: return std::sqrt(length_squared(shape.box().half_extents));
    case ShapeType::Polygon: return polygon_radius(shape.polygon()) + shape.polygon().rounding;
    case ShapeType::Capsule:
      return std::sqrt(std::max(length_squared(shape.capsule().center1),
                                length_squared(shape.capsule().center2))) +
             shape.capsule().radius;
    case ShapeType::Segment:
      return std::sqrt(std::max(length_squared(shape.segment().point1),
                                length_squared(shape.segment().point2)));
  }
  return 0.0f;
}

/// Radius (m) by which the shape's surface lies outside its core (its centre of curvature
/// under every rounded part): a circle's and a capsule's radius, a polygon's rounding; 0 for a
/// box, a sharp polygon and a segment.
inline float shape_rounding(const Shape& shape) {
  switch (shape.type()) {
    case ShapeType::Circle: return shape.circle().radius;
    case ShapeType::Capsule: return shape.capsule().radius;
    case ShapeType::Polygon: return shape.polygon().rounding;
    case ShapeType::Box:
    case ShapeType::Segment: return 0.0f;
  }
  return 0.0f;
}

/// A rectangle that rotates with its body: a 4-vertex polygon of the given half extents.
Shape make_oriented_box(vec2 half_extents);

/// Mass properties of a shape of uniform density.
struct MassData {
  float mass = 0.0f;     ///< kilograms (density * area)
  float inertia = 0.0f;  ///< kg m^2, about the centroid
  vec2 centroid{0.0f, 0.0f};  ///< metres, in the shape's coordinates
  float area = 0.0f;     ///< square metres
};

/// Mass, centroid and rotational inertia of `shape` at `density` (kg/m^2).
/// Disc: I = m r^2 / 2; box: I = m (w^2 + h^2) / 12; polygon: triangle fan, moved to the centroid
/// (rounded: plus the edge strips and corner sectors, see shape.cpp); capsule: rectangle plus
/// two half discs; segment: no area, mass 0.
MassData compute_mass(const Shape& shape, float density);

/// Mass properties of the raw polygon outline given (no re-centring), for tests and tools:
/// centroid in the input coordinates, inertia about that centroid.
MassData compute_polygon_mass(const vec2* vertices, int count, float density);

/// Axis-aligned bounds of a shape placed with `transform`.
struct Aabb {
  vec2 lower{0.0f, 0.0f};  ///< minimum corner, metres
  vec2 upper{0.0f, 0.0f};  ///< maximum corner, metres

  /// True when the two boxes overlap or touch.
  bool overlaps(const Aabb& other) const {
    return !(upper.x < other.lower.x || lower.x > other.upper.x || upper.y < other.lower.y ||
             lower.y > other.upper.y);
  }
  /// True when `point` lies inside or on the box.
  bool contains(vec2 point) const {
    return point.x >= lower.x && point.x <= upper.x && point.y >= lower.y && point.y <= upper.y;
  }
};

/// The world-space bounding box of `shape` under `transform`.
Aabb compute_aabb(const Shape& shape, const Transform& transform);

/// True when the world point lies inside (or on) the shape under `transform`.
bool shape_contains_point(const Shape& shape, const Transform& transform, vec2 point);

/// A ray hit on a shape.
struct ShapeRayHit {
  float fraction = 0.0f;     ///< position along the ray, 0 at origin, 1 at origin + translation
  vec2 normal{0.0f, 0.0f};   ///< outward unit surface normal at the hit
};

/// Casts the segment `origin` -> `origin + translation` against the shape. Returns true and
/// fills `hit` for the first entry point; a ray that starts inside the shape does not hit.
bool raycast_shape(const Shape& shape, const Transform& transform, vec2 origin, vec2 translation,
                   ShapeRayHit* hit);

}  // namespace impulse2d

/// @file shape.cpp
/// Shape construction with validation, mass properties, bounds, point and ray queries.
///
/// Boxes (`ShapeType::Box`) are axis-aligned by definition: every function here ignores
/// `transform.rotation` for a box and uses only `transform.position`. A rectangle that must
/// rotate is built with `make_oriented_box`, which gives a polygon.

#include "core/shape.h"

#include "core/collide.h"
#include "core/error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>

namespace impulse2d {

namespace {

constexpr float pi = 3.14159265358979323846f;

/// Relative tolerance of the polygon validation: edges shorter than this times the polygon's
/// size count as repeated points, turns whose sine is below it count as collinear, and an area
/// below it times the size squared counts as degenerate. 64 float epsilons (about 7.6e-6) is
/// far above the rounding of the normal and cross-product computations, so an accepted polygon
/// always has well-defined unit edge normals.
constexpr float polygon_tolerance = 64.0f * FLT_EPSILON;

std::string format_vertex(vec2 v) {
  std::ostringstream text;
  text.precision(9);
  text << "(" << v.x << ", " << v.y << ")";
  return text.str();
}

std::string format_number(float value) {
  std::ostringstream text;
  text.precision(9);
  text << value;
  return text.str();
}

[[noreturn]] void fail(const char* function, const std::string& reason) {
  throw Error(std::string(function) + ": " + reason);
}

int next_index(int index, int count) { return index + 1 < count ? index + 1 : 0; }

/// Twice the signed area of the outline (positive for counter-clockwise).
float twice_signed_area(const vec2* vertices, int count) {
  const vec2 origin = vertices[0];
  float sum = 0.0f;
  for (int i = 1; i + 1 < count; ++i) {
    sum += cross(vertices[i] - origin, vertices[i + 1] - origin);
  }
  return sum;
}

/// Checks everything `make_polygon` documents and throws `Error` naming the first problem.
void validate_polygon(const vec2* vertices, int count) {
  const char* function = "make_polygon";
  if (count < 3 || count > max_polygon_vertices) {
    fail(function, "count must be 3.." + std::to_string(max_polygon_vertices) + ", got " +
                       std::to_string(count));
  }
  if (vertices == nullptr) fail(function, "vertices is null");
  for (int i = 0; i < count; ++i) {
    if (!is_finite(vertices[i])) {
      fail(function,
           "vertex " + std::to_string(i) + " " + format_vertex(vertices[i]) + " is not finite");
    }
  }

  // Size of the outline, the scale every tolerance below is relative to.
  float size = 0.0f;
  for (int i = 1; i < count; ++i) size = std::max(size, glm::length(vertices[i] - vertices[0]));
  const float length_tolerance = polygon_tolerance * size;

  for (int i = 0; i < count; ++i) {
    for (int j = i + 1; j < count; ++j) {
      if (!(glm::length(vertices[j] - vertices[i]) > length_tolerance)) {
        fail(function, "vertices " + std::to_string(i) + " and " + std::to_string(j) + " " +
                           format_vertex(vertices[i]) + " are repeated");
      }
    }
  }

  const float area_twice = twice_signed_area(vertices, count);
  const float area_tolerance = polygon_tolerance * size * size;
  if (area_twice < -area_tolerance) {
    fail(function, "vertices are in clockwise order (signed area " +
                       format_number(0.5f * area_twice) + "); counter-clockwise is required");
  }
  if (!(area_twice > area_tolerance)) {
    fail(function, "the area " + format_number(0.5f * area_twice) + " is near zero");
  }

  for (int i = 0; i < count; ++i) {
    const int j = next_index(i, count);
    const int k = next_index(j, count);
    const vec2 edge_in = vertices[j] - vertices[i];
    const vec2 edge_out = vertices[k] - vertices[j];
    const float turn = cross(edge_in, edge_out);
    const float turn_tolerance = polygon_tolerance * glm::length(edge_in) * glm::length(edge_out);
    if (std::fabs(turn) <= turn_tolerance) {
      fail(function, "vertices " + std::to_string(i) + ", " + std::to_string(j) + ", " +
                         std::to_string(k) + " are collinear");
    }
    if (turn < 0.0f) {
      fail(function, "the outline is not convex at vertex " + std::to_string(j) + " " +
                         format_vertex(vertices[j]));
    }
  }

  // Every left turn is not enough: a star winds around twice. A convex outline has every
  // vertex strictly inside every edge's half-plane.
  for (int i = 0; i < count; ++i) {
    const int j = next_index(i, count);
    const vec2 edge = vertices[j] - vertices[i];
    for (int v = 0; v < count; ++v) {
      if (v == i || v == j) continue;
      const vec2 offset = vertices[v] - vertices[i];
      if (!(cross(edge, offset) > polygon_tolerance * glm::length(edge) * glm::length(offset))) {
        fail(function, "the outline is self-overlapping: vertex " + std::to_string(v) +
                           " is not inside edge " + std::to_string(i) + " -> " + std::to_string(j));
      }
    }
  }
}

void validate_half_extents(const char* function, vec2 half_extents) {
  const char* names[2] = {"half_extents.x", "half_extents.y"};
  for (int axis = 0; axis < 2; ++axis) {
    const float value = half_extents[axis];
    if (!std::isfinite(value) || !(value > 0.0f)) {
      fail(function,
           std::string(names[axis]) + " must be finite and > 0, got " + format_number(value));
    }
  }
}

void validate_density(const char* function, float density) {
  if (!std::isfinite(density) || density < 0.0f) {
    fail(function, "density must be finite and >= 0, got " + format_number(density));
  }
}

void validate_rounding(const char* function, float rounding) {
  if (!std::isfinite(rounding) || rounding < 0.0f) {
    fail(function, "radius must be finite and >= 0, got " + format_number(rounding));
  }
}

/// Checks two end points of a capsule or segment: finite, and apart by more than the polygon
/// tolerance times their size (so the direction between them is well defined).
void validate_ends(const char* function, const char* first, vec2 p1, const char* second, vec2 p2,
                   const char* too_close) {
  if (!is_finite(p1)) fail(function, std::string(first) + " " + format_vertex(p1) + " is not finite");
  if (!is_finite(p2)) fail(function, std::string(second) + " " + format_vertex(p2) + " is not finite");
  const float size = std::max(std::max(std::fabs(p1.x), std::fabs(p1.y)),
                              std::max(std::fabs(p2.x), std::fabs(p2.y)));
  if (!(glm::length(p2 - p1) > polygon_tolerance * std::max(size, 1.0f))) {
    fail(function, std::string(first) + " and " + second + " " + format_vertex(p1) + " are " +
                       too_close);
  }
}

/// Capsule mass properties (centroid: the midpoint of the centres). The solid is a rectangle
/// L x 2r (L = |center2 - center1|) and two half discs, which together have a disc's area
/// pi r^2. Rectangle: I = m_rect (L^2 + 4 r^2) / 12. Each half disc (mass m_disc / 2) has its
/// centroid lc = 4 r / (3 pi) from its flat side, so about its own centroid
/// I = (m_disc / 2) (r^2 / 2 - lc^2); moved out to h + lc from the capsule's centroid
/// (h = L / 2) it adds (m_disc / 2) (h + lc)^2. Both: m_disc (r^2 / 2 + h^2 + 2 h lc).
MassData capsule_mass(const Capsule& capsule, float density) {
  const float radius = capsule.radius;
  const float length = glm::length(capsule.center2 - capsule.center1);
  const float disc_area = pi * radius * radius;
  const float rectangle_area = 2.0f * radius * length;
  const float half_length = 0.5f * length;
  const float cap_centroid = 4.0f * radius / (3.0f * pi);
  MassData mass_data;
  mass_data.area = disc_area + rectangle_area;
  mass_data.mass = density * mass_data.area;
  mass_data.centroid = 0.5f * (capsule.center1 + capsule.center2);
  const float disc_inertia =
      density * disc_area *
      (0.5f * radius * radius + half_length * half_length + 2.0f * half_length * cap_centroid);
  const float rectangle_inertia =
      density * rectangle_area * (length * length + 4.0f * radius * radius) / 12.0f;
  mass_data.inertia = disc_inertia + rectangle_inertia;
  return mass_data;
}

/// Mass properties of a convex polygon (CCW, 3.. vertices, in any coordinates) swollen by
/// `rounding` > 0. The solid splits into three kinds of piece, each summed as an area, a first
/// moment and a second (polar) moment about the coordinate origin:
///  - the core polygon: the triangle fan of `compute_polygon_mass`;
///  - one strip per edge, the rectangle between the edge and the edge pushed out by r along its
///    outward normal n: the fan formula on the quad (p1, p1 + r n, p2 + r n, p2);
///  - one circular sector per vertex v, of radius r and angle theta from the previous edge's
///    normal to the next one's (the angles add up to 2 pi: the sectors make one disc). About
///    its apex a sector has area theta r^2 / 2, first moment (2/3) r^3 sin(theta / 2) along
///    its bisector b, and polar moment theta r^4 / 4; moved to the origin
///    (J_o = J_v + A |v|^2 + 2 v . (first moment about v)).
/// Then the centroid is the first moment over the area and the inertia the polar moment moved
/// to the centroid (parallel axis). Sums are taken relative to vertex 0 for precision.
MassData rounded_polygon_mass(const vec2* vertices, int count, float rounding, float density) {
  const vec2 origin = vertices[0];
  const float r = rounding;
  double area = 0.0;
  double moment_x = 0.0;
  double moment_y = 0.0;
  double second = 0.0;
  // One triangle (0, p1, p2) of a fan about `origin`: adds its area and moments.
  auto add_triangle = [&](vec2 p1, vec2 p2) {
    const double twice_triangle_area = static_cast<double>(cross(p1, p2));
    area += 0.5 * twice_triangle_area;
    moment_x += twice_triangle_area / 6.0 * (static_cast<double>(p1.x) + p2.x);
    moment_y += twice_triangle_area / 6.0 * (static_cast<double>(p1.y) + p2.y);
    second += twice_triangle_area / 12.0 *
              (static_cast<double>(p1.x) * p1.x + static_cast<double>(p1.x) * p2.x +
               static_cast<double>(p2.x) * p2.x + static_cast<double>(p1.y) * p1.y +
               static_cast<double>(p1.y) * p2.y + static_cast<double>(p2.y) * p2.y);
  };
  vec2 normals[max_polygon_vertices];
  for (int i = 0; i < count; ++i) {
    const vec2 edge = vertices[next_index(i, count)] - vertices[i];
    normals[i] = glm::normalize(right_perpendicular(edge));
  }
  for (int i = 0; i < count; ++i) {
    const vec2 p1 = vertices[i] - origin;
    const vec2 p2 = vertices[next_index(i, count)] - origin;
    add_triangle(p1, p2);  // core
    // The strip (p1, p1 + r n, p2 + r n, p2) as a fan about the origin.
    const vec2 q1 = p1 + r * normals[i];
    const vec2 q2 = p2 + r * normals[i];
    add_triangle(p1, q1);
    add_triangle(q1, q2);
    add_triangle(q2, p2);
    add_triangle(p2, p1);
  }
  for (int i = 0; i < count; ++i) {
    const vec2 before = normals[i == 0 ? count - 1 : i - 1];
    const vec2 after = normals[i];
    const double theta = std::atan2(static_cast<double>(cross(before, after)),
                                    static_cast<double>(glm::dot(before, after)));
    const vec2 bisector = glm::normalize(before + after);
    const vec2 v = vertices[i] - origin;
    const double rr = static_cast<double>(r) * r;
    const double sector_area = 0.5 * theta * rr;
    const double apex_moment = 2.0 / 3.0 * rr * r * std::sin(0.5 * theta);  // along the bisector
    area += sector_area;
    moment_x += sector_area * v.x + apex_moment * bisector.x;
    moment_y += sector_area * v.y + apex_moment * bisector.y;
    second += 0.25 * theta * rr * rr + sector_area * length_squared(v) +
              2.0 * apex_moment * glm::dot(v, bisector);
  }
  const double centroid_x = moment_x / area;
  const double centroid_y = moment_y / area;
  MassData mass_data;
  mass_data.area = static_cast<float>(area);
  mass_data.mass = density * mass_data.area;
  mass_data.centroid = origin + vec2(static_cast<float>(centroid_x), static_cast<float>(centroid_y));
  mass_data.inertia = static_cast<float>(
      density * (second - area * (centroid_x * centroid_x + centroid_y * centroid_y)));
  return mass_data;
}

/// The box's bounds: a box ignores the rotation of its transform.
Aabb box_bounds(const Box& box, const Transform& transform) {
  return {transform.position - box.half_extents, transform.position + box.half_extents};
}

bool raycast_circle(const Circle& circle, vec2 centre, vec2 origin, vec2 translation,
                    ShapeRayHit* hit) {
  const vec2 from_centre = origin - centre;
  const float radius_squared = circle.radius * circle.radius;
  if (length_squared(from_centre) <= radius_squared) return false;  // starts inside
  const float ray_length = glm::length(translation);
  if (!(ray_length > 0.0f)) return false;
  const vec2 direction = translation / ray_length;
  // Closest approach of the infinite line to the centre, measured along the ray; working from
  // the projection keeps precision for short rays far from the centre.
  const float along = -glm::dot(from_centre, direction);
  const vec2 closest = from_centre + along * direction;
  const float half_chord_squared = radius_squared - length_squared(closest);
  if (half_chord_squared < 0.0f) return false;
  const float entry = along - std::sqrt(half_chord_squared);
  if (entry < 0.0f || entry > ray_length) return false;
  if (hit != nullptr) {
    hit->fraction = entry / ray_length;
    hit->normal = glm::normalize(from_centre + entry * direction);
  }
  return true;
}

bool raycast_box(const Box& box, const Transform& transform, vec2 origin, vec2 translation,
                 ShapeRayHit* hit) {
  const Aabb bounds = box_bounds(box, transform);
  if (bounds.contains(origin)) return false;
  float entry = 0.0f;
  float exit = 1.0f;
  int entry_axis = -1;
  for (int axis = 0; axis < 2; ++axis) {
    const float start = origin[axis];
    const float step = translation[axis];
    if (step == 0.0f) {
      if (start < bounds.lower[axis] || start > bounds.upper[axis]) return false;
      continue;
    }
    float near_fraction = (bounds.lower[axis] - start) / step;
    float far_fraction = (bounds.upper[axis] - start) / step;
    if (near_fraction > far_fraction) std::swap(near_fraction, far_fraction);
    if (near_fraction > entry) {
      entry = near_fraction;
      entry_axis = axis;
    }
    exit = std::min(exit, far_fraction);
    if (entry > exit) return false;
  }
  if (entry_axis < 0) return false;
  if (hit != nullptr) {
    hit->fraction = entry;
    hit->normal = vec2(0.0f, 0.0f);
    hit->normal[entry_axis] = translation[entry_axis] > 0.0f ? -1.0f : 1.0f;
  }
  return true;
}

bool raycast_polygon(const Polygon& polygon, const Transform& transform, vec2 origin,
                     vec2 translation, ShapeRayHit* hit) {
  const vec2 local_origin = transform.apply_inverse(origin);
  const vec2 local_translation = transform.rotation.inverse_rotate(translation);
  float entry = 0.0f;
  float exit = 1.0f;
  int entry_edge = -1;
  bool starts_inside = true;
  for (int i = 0; i < polygon.count; ++i) {
    const vec2 normal = polygon.normals[i];
    // Along the ray the signed distance to edge i's line is distance_to_line - fraction * rate.
    const float distance_to_line = glm::dot(normal, polygon.vertices[i] - local_origin);
    const float approach = glm::dot(normal, local_translation);
    if (distance_to_line < 0.0f) starts_inside = false;
    if (approach == 0.0f) {
      if (distance_to_line < 0.0f) return false;  // parallel and outside this edge
      continue;
    }
    const float crossing = distance_to_line / approach;
    if (approach < 0.0f) {
      if (crossing > entry) {
        entry = crossing;
        entry_edge = i;
      }
    } else {
      exit = std::min(exit, crossing);
    }
    if (entry > exit) return false;
  }
  if (starts_inside || entry_edge < 0) return false;
  if (hit != nullptr) {
    hit->fraction = entry;
    hit->normal = transform.rotation.rotate(polygon.normals[entry_edge]);
  }
  return true;
}

/// Squared distance (m^2) from `point` to the segment from `start` to `end`.
float distance_squared_to_segment(vec2 point, vec2 start, vec2 end) {
  const vec2 edge = end - start;
  const float edge_squared = length_squared(edge);
  float t = edge_squared > 0.0f ? glm::dot(point - start, edge) / edge_squared : 0.0f;
  t = std::min(std::max(t, 0.0f), 1.0f);
  return length_squared(point - (start + t * edge));
}

/// True when the body-local `point` lies within `rounding` of the polygon's core (inside it or
/// within that distance of an edge).
bool rounded_polygon_contains(const Polygon& polygon, vec2 point) {
  bool inside = true;
  for (int i = 0; i < polygon.count; ++i) {
    if (glm::dot(polygon.normals[i], point - polygon.vertices[i]) > 0.0f) inside = false;
  }
  if (inside) return true;
  const float reach_squared = polygon.rounding * polygon.rounding;
  for (int i = 0; i < polygon.count; ++i) {
    const vec2 start = polygon.vertices[i];
    const vec2 end = polygon.vertices[next_index(i, polygon.count)];
    if (distance_squared_to_segment(point, start, end) <= reach_squared) return true;
  }
  return false;
}

/// The rectangle swept by pushing edge start -> end (of a CCW outline, outward normal
/// `normal`) out by `depth` to both sides when `both_sides`, else outward only: a 4-vertex
/// polygon in the same coordinates.
Polygon edge_strip(vec2 start, vec2 end, vec2 normal, float depth, bool both_sides) {
  const vec2 inner_offset = both_sides ? -depth * normal : vec2(0.0f);
  Polygon strip;
  strip.count = 4;
  strip.vertices[0] = start + inner_offset;
  strip.vertices[1] = end + inner_offset;
  strip.vertices[2] = end + depth * normal;
  strip.vertices[3] = start + depth * normal;
  // Counter-clockwise when the normal is the right perpendicular of start -> end, reversed
  // otherwise: take the normals from the vertex order.
  const float turn = cross(strip.vertices[1] - strip.vertices[0], strip.vertices[2] - strip.vertices[1]);
  if (turn < 0.0f) {
    std::swap(strip.vertices[1], strip.vertices[3]);
  }
  for (int i = 0; i < 4; ++i) {
    const vec2 edge = strip.vertices[next_index(i, 4)] - strip.vertices[i];
    strip.normals[i] = glm::normalize(right_perpendicular(edge));
  }
  return strip;
}

/// Keeps the nearer of two ray hits.
void keep_nearer(bool found, const ShapeRayHit& candidate, bool* any, ShapeRayHit* best) {
  if (found && (!*any || candidate.fraction < best->fraction)) {
    *best = candidate;
    *any = true;
  }
}

/// A ray against the union of convex pieces (the ray starts outside all of them): the first
/// entry into the union is the earliest entry into any piece.
bool raycast_rounded_outline(const vec2* vertices, const vec2* normals, int count, float rounding,
                             const Transform& transform, vec2 origin, vec2 translation,
                             ShapeRayHit* hit) {
  bool any = false;
  ShapeRayHit best;
  ShapeRayHit candidate;
  const Circle corner{rounding};
  if (count >= 3) {
    Polygon core;
    core.count = count;
    for (int i = 0; i < count; ++i) {
      core.vertices[i] = vertices[i];
      core.normals[i] = normals[i];
    }
    keep_nearer(raycast_polygon(core, transform, origin, translation, &candidate), candidate,
                &any, &best);
  }
  const int edge_count = count == 2 ? 1 : count;
  for (int i = 0; i < count; ++i) {
    keep_nearer(raycast_circle(corner, transform.apply(vertices[i]), origin, translation, &candidate),
                candidate, &any, &best);
  }
  for (int i = 0; i < edge_count; ++i) {
    const Polygon strip = edge_strip(vertices[i], vertices[next_index(i, count)], normals[i],
                                     rounding, count == 2);
    keep_nearer(raycast_polygon(strip, transform, origin, translation, &candidate), candidate,
                &any, &best);
  }
  if (any && hit != nullptr) *hit = best;
  return any;
}

/// The segment's ray hit: the crossing of the two lines within both, normal facing the ray.
bool raycast_segment(const Segment& segment, const Transform& transform, vec2 origin,
                     vec2 translation, ShapeRayHit* hit) {
  const vec2 start = transform.apply(segment.point1);
  const vec2 edge = transform.apply(segment.point2) - start;
  const float denominator = cross(translation, edge);
  if (denominator == 0.0f) return false;  // parallel (or a zero-length ray)
  const vec2 offset = start - origin;
  const float fraction = cross(offset, edge) / denominator;
  const float along = cross(offset, translation) / denominator;
  if (!(fraction > 0.0f && fraction <= 1.0f && along >= 0.0f && along <= 1.0f)) return false;
  // A chain link is hit from its front (left) side only.
  if (segment.one_sided && cross(edge, translation) >= 0.0f) return false;
  if (hit != nullptr) {
    vec2 normal = glm::normalize(right_perpendicular(edge));
    if (glm::dot(normal, translation) > 0.0f) normal = -normal;
    hit->fraction = fraction;
    hit->normal = normal;
  }
  return true;
}

}  // namespace

Shape make_circle(float radius) {
  if (!std::isfinite(radius) || !(radius > 0.0f)) {
    fail("make_circle", "radius must be finite and > 0, got " + format_number(radius));
  }
  return Circle{radius};
}

Shape make_box(vec2 half_extents) {
  validate_half_extents("make_box", half_extents);
  return Box{half_extents};
}

Shape make_polygon(const vec2* vertices, int count, vec2* centroid_out) {
  validate_polygon(vertices, count);
  const vec2 centroid = compute_polygon_mass(vertices, count, 1.0f).centroid;
  Polygon polygon;
  polygon.count = count;
  for (int i = 0; i < count; ++i) polygon.vertices[i] = vertices[i] - centroid;
  for (int i = 0; i < count; ++i) {
    const vec2 edge = polygon.vertices[next_index(i, count)] - polygon.vertices[i];
    polygon.normals[i] = glm::normalize(right_perpendicular(edge));
  }
  polygon.radius = farthest_vertex_distance(polygon);
  if (centroid_out != nullptr) *centroid_out = centroid;
  return polygon;
}

Shape make_rounded_polygon(const vec2* vertices, int count, float rounding, vec2* centroid_out) {
  validate_rounding("make_rounded_polygon", rounding);
  if (rounding == 0.0f) return make_polygon(vertices, count, centroid_out);
  validate_polygon(vertices, count);
  // The rounded solid's centroid (edge strips and corner sectors shift it from the core's).
  const vec2 centroid = rounded_polygon_mass(vertices, count, rounding, 1.0f).centroid;
  vec2 shifted[max_polygon_vertices];
  for (int i = 0; i < count; ++i) shifted[i] = vertices[i] - centroid;
  Polygon polygon;
  polygon.count = count;
  for (int i = 0; i < count; ++i) polygon.vertices[i] = shifted[i];
  for (int i = 0; i < count; ++i) {
    const vec2 edge = polygon.vertices[next_index(i, count)] - polygon.vertices[i];
    polygon.normals[i] = glm::normalize(right_perpendicular(edge));
  }
  polygon.radius = farthest_vertex_distance(polygon);
  polygon.rounding = rounding;
  if (centroid_out != nullptr) *centroid_out = centroid;
  return polygon;
}

Shape make_capsule(vec2 center1, vec2 center2, float radius, vec2* centroid_out) {
  const char* function = "make_capsule";
  validate_ends(function, "center1", center1, "center2", center2,
                "equal (use a circle for a capsule of zero length)");
  if (!std::isfinite(radius) || !(radius > 0.0f)) {
    fail(function, "radius must be finite and > 0, got " + format_number(radius));
  }
  const vec2 centroid = 0.5f * (center1 + center2);
  if (centroid_out != nullptr) *centroid_out = centroid;
  return Capsule{center1 - centroid, center2 - centroid, radius};
}

Shape make_segment(vec2 point1, vec2 point2, vec2* centroid_out) {
  validate_ends("make_segment", "point1", point1, "point2", point2,
                "equal (a segment needs a length > 0)");
  const vec2 centroid = 0.5f * (point1 + point2);
  if (centroid_out != nullptr) *centroid_out = centroid;
  return Segment{point1 - centroid, point2 - centroid};
}

std::vector<ChainLink> make_chain(const vec2* points, int count, bool loop) {
  const char* function = "make_chain";
  constexpr int max_points = 100000;
  const int least = loop ? 3 : 2;
  if (count < least || count > max_points) {
    fail(function, std::string(loop ? "a loop" : "an open chain") + " needs " +
                       std::to_string(least) + ".." + std::to_string(max_points) +
                       " points, got " + std::to_string(count));
  }
  auto name = [](int i) { return "points[" + std::to_string(i) + "]"; };
  for (int i = 0; i < count; ++i) {
    if (!is_finite(points[i])) fail(function, name(i) + " " + format_vertex(points[i]) + " is not finite");
  }
  for (int i = 1; i < count; ++i) {
    validate_ends(function, name(i - 1).c_str(), points[i - 1], name(i).c_str(), points[i],
                  "equal (consecutive chain points must differ)");
  }
  if (loop) {
    validate_ends(function, name(count - 1).c_str(), points[count - 1], name(0).c_str(), points[0],
                  "equal (a loop closes itself: do not repeat the first point at the end)");
  }
  const int links = loop ? count : count - 1;
  auto point = [&](int i) { return points[(i + count) % count]; };
  std::vector<ChainLink> chain;
  chain.reserve(static_cast<std::size_t>(links));
  for (int i = 0; i < links; ++i) {
    const vec2 point1 = point(i);
    const vec2 point2 = point(i + 1);
    // An open chain's ends have no neighbour: the ghost is the end point itself.
    const vec2 ghost1 = (loop || i > 0) ? point(i - 1) : point1;
    const vec2 ghost2 = (loop || i + 1 < links) ? point(i + 2) : point2;
    const vec2 midpoint = 0.5f * (point1 + point2);
    Segment segment{point1 - midpoint, point2 - midpoint};
    segment.one_sided = true;
    segment.ghost1 = ghost1 - midpoint;
    segment.ghost2 = ghost2 - midpoint;
    chain.push_back(ChainLink{Shape(segment), midpoint});
  }
  return chain;
}

float farthest_vertex_distance(const Polygon& polygon) {
  float farthest_squared = 0.0f;
  for (int i = 0; i < polygon.count; ++i) {
    farthest_squared = std::max(farthest_squared, length_squared(polygon.vertices[i]));
  }
  return std::sqrt(farthest_squared);
}

Shape make_oriented_box(vec2 half_extents) {
  validate_half_extents("make_oriented_box", half_extents);
  Polygon polygon = box_as_polygon(Box{half_extents});
  polygon.radius = farthest_vertex_distance(polygon);
  return polygon;
}

MassData compute_polygon_mass(const vec2* vertices, int count, float density) {
  const char* function = "compute_polygon_mass";
  if (vertices == nullptr) fail(function, "vertices is null");
  if (count < 3) fail(function, "count must be >= 3, got " + std::to_string(count));
  validate_density(function, density);

  // Triangle fan from vertex 0; sums taken relative to it to keep the numbers small.
  const vec2 origin = vertices[0];
  float area = 0.0f;
  vec2 centroid_moment{0.0f, 0.0f};
  float second_moment = 0.0f;  // of area, about `origin`
  for (int i = 0; i < count; ++i) {
    const vec2 p1 = vertices[i] - origin;
    const vec2 p2 = vertices[next_index(i, count)] - origin;
    const float twice_triangle_area = cross(p1, p2);
    area += 0.5f * twice_triangle_area;
    centroid_moment += (twice_triangle_area / 6.0f) * (p1 + p2);
    second_moment += (twice_triangle_area / 12.0f) * (p1.x * p1.x + p1.x * p2.x + p2.x * p2.x +
                                                      p1.y * p1.y + p1.y * p2.y + p2.y * p2.y);
  }
  if (!(area > 0.0f)) {
    fail(function, "the outline has area " + format_number(area) +
                       "; a counter-clockwise, non-degenerate outline is required");
  }
  const vec2 centroid_offset = centroid_moment / area;
  MassData mass_data;
  mass_data.area = area;
  mass_data.mass = density * area;
  mass_data.centroid = origin + centroid_offset;
  // Parallel axis theorem: move the second moment from `origin` to the centroid.
  mass_data.inertia = density * (second_moment - area * length_squared(centroid_offset));
  return mass_data;
}

MassData compute_mass(const Shape& shape, float density) {
  validate_density("compute_mass", density);
  MassData mass_data;
  switch (shape.type()) {
    case ShapeType::Circle: {
      const float radius = shape.circle().radius;
      mass_data.area = pi * radius * radius;
      mass_data.mass = density * mass_data.area;
      mass_data.inertia = 0.5f * mass_data.mass * radius * radius;
      return mass_data;
    }
    case ShapeType::Box: {
      const float width = 2.0f * shape.box().half_extents.x;
      const float height = 2.0f * shape.box().half_extents.y;
      mass_data.area = width * height;
      mass_data.mass = density * mass_data.area;
      mass_data.inertia = mass_data.mass * (width * width + height * height) / 12.0f;
      return mass_data;
    }
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      if (polygon.rounding > 0.0f) {
        return rounded_polygon_mass(polygon.vertices.data(), polygon.count, polygon.rounding,
                                    density);
      }
      return compute_polygon_mass(polygon.vertices.data(), polygon.count, density);
    }
    case ShapeType::Capsule:
      return capsule_mass(shape.capsule(), density);
    case ShapeType::Segment:
      mass_data.centroid = 0.5f * (shape.segment().point1 + shape.segment().point2);
      return mass_data;
  }
  fail("compute_mass", "unknown shape type " + std::to_string(static_cast<int>(shape.type())));
}

Aabb compute_aabb(const Shape& shape, const Transform& transform) {
  switch (shape.type()) {
    case ShapeType::Circle: {
      const vec2 reach(shape.circle().radius, shape.circle().radius);
      return {transform.position - reach, transform.position + reach};
    }
    case ShapeType::Box:
      return box_bounds(shape.box(), transform);
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      Aabb bounds;
      bounds.lower = bounds.upper = transform.apply(polygon.vertices[0]);
      for (int i = 1; i < polygon.count; ++i) {
        const vec2 corner = transform.apply(polygon.vertices[i]);
        bounds.lower = glm::min(bounds.lower, corner);
        bounds.upper = glm::max(bounds.upper, corner);
      }
      if (polygon.rounding > 0.0f) {
        bounds.lower -= vec2(polygon.rounding);
        bounds.upper += vec2(polygon.rounding);
      }
      return bounds;
    }
    case ShapeType::Capsule: {
      const vec2 c1 = transform.apply(shape.capsule().center1);
      const vec2 c2 = transform.apply(shape.capsule().center2);
      const vec2 reach(shape.capsule().radius);
      return {glm::min(c1, c2) - reach, glm::max(c1, c2) + reach};
    }
    case ShapeType::Segment: {
      const vec2 p1 = transform.apply(shape.segment().point1);
      const vec2 p2 = transform.apply(shape.segment().point2);
      return {glm::min(p1, p2), glm::max(p1, p2)};
    }
  }
  fail("compute_aabb", "unknown shape type " + std::to_string(static_cast<int>(shape.type())));
}

bool shape_contains_point(const Shape& shape, const Transform& transform, vec2 point) {
  switch (shape.type()) {
    case ShapeType::Circle:
      return length_squared(point - transform.position) <=
             shape.circle().radius * shape.circle().radius;
    case ShapeType::Box:
      return box_bounds(shape.box(), transform).contains(point);
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      const vec2 local_point = transform.apply_inverse(point);
      if (polygon.rounding > 0.0f) return rounded_polygon_contains(polygon, local_point);
      for (int i = 0; i < polygon.count; ++i) {
        if (glm::dot(polygon.normals[i], local_point - polygon.vertices[i]) > 0.0f) return false;
      }
      return true;
    }
    case ShapeType::Capsule: {
      const Capsule& capsule = shape.capsule();
      return distance_squared_to_segment(transform.apply_inverse(point), capsule.center1,
                                         capsule.center2) <= capsule.radius * capsule.radius;
    }
    case ShapeType::Segment:
      return false;  // no area: nothing lies inside
  }
  fail("shape_contains_point",
       "unknown shape type " + std::to_string(static_cast<int>(shape.type())));
}

bool raycast_shape(const Shape& shape, const Transform& transform, vec2 origin, vec2 translation,
                   ShapeRayHit* hit) {
  switch (shape.type()) {
    case ShapeType::Circle:
      return raycast_circle(shape.circle(), transform.position, origin, translation, hit);
    case ShapeType::Box:
      return raycast_box(shape.box(), transform, origin, translation, hit);
    case ShapeType::Polygon: {
      const Polygon& polygon = shape.polygon();
      if (!(polygon.rounding > 0.0f)) return raycast_polygon(polygon, transform, origin, translation, hit);
      if (shape_contains_point(shape, transform, origin)) return false;  // starts inside
      return raycast_rounded_outline(polygon.vertices.data(), polygon.normals.data(), polygon.count,
                                     polygon.rounding, transform, origin, translation, hit);
    }
    case ShapeType::Capsule: {
      const Capsule& capsule = shape.capsule();
      if (shape_contains_point(shape, transform, origin)) return false;  // starts inside
      const vec2 vertices[2] = {capsule.center1, capsule.center2};
      const vec2 normal = glm::normalize(right_perpendicular(capsule.center2 - capsule.center1));
      const vec2 normals[2] = {normal, -normal};
      return raycast_rounded_outline(vertices, normals, 2, capsule.radius, transform, origin,
                                     translation, hit);
    }
    case ShapeType::Segment:
      return raycast_segment(shape.segment(), transform, origin, translation, hit);
  }
  fail("raycast_shape", "unknown shape type " + std::to_string(static_cast<int>(shape.type())));
}

void validate_shape(const Shape& shape, const std::string& caller) {
  switch (shape.type()) {
    case ShapeType::Circle:
      if (!(std::isfinite(shape.circle().radius) && shape.circle().radius > 0.0f)) {
        throw Error(caller + ": circle radius must be finite and > 0");
      }
      return;
    case ShapeType::Box:
      if (!(is_finite(shape.box().half_extents) && shape.box().half_extents.x > 0.0f &&
            shape.box().half_extents.y > 0.0f)) {
        throw Error(caller + ": box half extents must be finite and > 0");
      }
      return;
    case ShapeType::Polygon:
      if (shape.polygon().count < 3 || shape.polygon().count > max_polygon_vertices) {
        throw Error(caller + ": polygon needs 3..8 vertices (use make_polygon)");
      }
      if (!(std::isfinite(shape.polygon().rounding) && shape.polygon().rounding >= 0.0f)) {
        throw Error(caller + ": polygon rounding radius must be finite and >= 0");
      }
      return;
    case ShapeType::Capsule: {
      const Capsule& capsule = shape.capsule();
      if (!(std::isfinite(capsule.radius) && capsule.radius > 0.0f)) {
        throw Error(caller + ": capsule radius must be finite and > 0");
      }
      if (!(is_finite(capsule.center1) && is_finite(capsule.center2)) || capsule.center1 == capsule.center2) {
        throw Error(caller + ": capsule centres must be finite and differ (use make_capsule)");
      }
      return;
    }
    case ShapeType::Segment:
      if (!(is_finite(shape.segment().point1) && is_finite(shape.segment().point2)) ||
          shape.segment().point1 == shape.segment().point2) {
        throw Error(caller + ": segment points must be finite and differ (use make_segment)");
      }
      if (shape.segment().one_sided &&
          !(is_finite(shape.segment().ghost1) && is_finite(shape.segment().ghost2))) {
        throw Error(caller + ": chain link ghost points must be finite (use make_chain)");
      }
      return;
  }
  throw Error(caller + ": unknown shape type");
}

}  // namespace impulse2d

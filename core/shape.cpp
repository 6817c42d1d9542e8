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
    case ShapeType::Polygon:
      return compute_polygon_mass(shape.polygon().vertices.data(), shape.polygon().count, density);
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
      return bounds;
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
      for (int i = 0; i < polygon.count; ++i) {
        if (glm::dot(polygon.normals[i], local_point - polygon.vertices[i]) > 0.0f) return false;
      }
      return true;
    }
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
    case ShapeType::Polygon:
      return raycast_polygon(shape.polygon(), transform, origin, translation, hit);
  }
  fail("raycast_shape", "unknown shape type " + std::to_string(static_cast<int>(shape.type())));
}

}  // namespace impulse2d

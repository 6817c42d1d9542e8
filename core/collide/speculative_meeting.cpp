#include "core/collide/speculative_meeting.h"

#include "core/collide/speculative_reach.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse2d {

namespace {

// A shape as a convex outline (1 point for a disc, 4 for a box, n for a polygon) grown by a
// radius, its outline in coordinates relative to a shared origin (A's centre) so that the
// arithmetic keeps its precision far from the world origin.
struct RoundedOutline {
  vec2 vertices[max_polygon_vertices];
  int count = 0;
  float radius = 0.0f;  // metres
};

RoundedOutline outline_of(const Shape& shape, const Transform& transform, vec2 origin) {
  RoundedOutline outline;
  const vec2 centre = transform.position - origin;
  switch (shape.type()) {
    case ShapeType::Circle:
      outline.vertices[0] = centre;
      outline.count = 1;
      outline.radius = shape.circle().radius;
      break;
    case ShapeType::Box: {
      const vec2 half = shape.box().half_extents;
      outline.vertices[0] = centre + vec2(-half.x, -half.y);
      outline.vertices[1] = centre + vec2(half.x, -half.y);
      outline.vertices[2] = centre + vec2(half.x, half.y);
      outline.vertices[3] = centre + vec2(-half.x, half.y);
      outline.count = 4;
      break;
    }
    case ShapeType::Polygon:
      outline.count = shape.polygon().count;
      for (int i = 0; i < outline.count; ++i) {
        outline.vertices[i] = centre + transform.rotation.rotate(shape.polygon().vertices[i]);
      }
      outline.radius = shape.polygon().rounding;
      break;
    case ShapeType::Capsule:
      outline.vertices[0] = centre + transform.rotation.rotate(shape.capsule().center1);
      outline.vertices[1] = centre + transform.rotation.rotate(shape.capsule().center2);
      outline.count = 2;
      outline.radius = shape.capsule().radius;
      break;
    case ShapeType::Segment:
      outline.vertices[0] = centre + transform.rotation.rotate(shape.segment().point1);
      outline.vertices[1] = centre + transform.rotation.rotate(shape.segment().point2);
      outline.count = 2;
      break;
  }
  return outline;
}

// Squared distance (m^2) from `p` to the segment from `s0` to `s1`.
float segment_distance_squared(vec2 p, vec2 s0, vec2 s1) {
  const vec2 edge = s1 - s0;
  const float edge_length_squared = glm::dot(edge, edge);
  float t = edge_length_squared > 0.0f ? glm::dot(p - s0, edge) / edge_length_squared : 0.0f;
  t = std::min(std::max(t, 0.0f), 1.0f);
  const vec2 offset = p - (s0 + edge * t);
  return glm::dot(offset, offset);
}

// True when `p` lies inside or on the counter-clockwise convex outline (>= 3 vertices).
bool contains(const RoundedOutline& outline, vec2 p) {
  for (int i = 0; i < outline.count; ++i) {
    const vec2 v0 = outline.vertices[i];
    const vec2 v1 = outline.vertices[(i + 1) % outline.count];
    if (cross(v1 - v0, p - v0) < 0.0f) return false;
  }
  return true;
}

// Squared distance (m^2) from `p` to the outline's boundary, or 0 when inside.
float point_distance_squared(const RoundedOutline& outline, vec2 p) {
  if (outline.count == 1) {
    const vec2 offset = p - outline.vertices[0];
    return glm::dot(offset, offset);
  }
  if (contains(outline, p)) return 0.0f;
  float nearest = std::numeric_limits<float>::max();
  for (int i = 0; i < outline.count; ++i) {
    nearest = std::min(nearest, segment_distance_squared(p, outline.vertices[i],
                                                         outline.vertices[(i + 1) % outline.count]));
  }
  return nearest;
}

// Distance (m) between the two bare outlines, B shifted by `shift`: 0 when they overlap.
// Disjoint convex outlines are nearest at a vertex of one against the other. Overlapping ones
// have a vertex of one inside the other, or else edges that cross (two thin bars laid as a
// plus sign), so crossing edges are tested too.
float outline_distance(const RoundedOutline& a, const RoundedOutline& b, vec2 shift) {
  RoundedOutline moved = b;
  for (int i = 0; i < b.count; ++i) moved.vertices[i] += shift;
  float nearest = std::numeric_limits<float>::max();
  for (int i = 0; i < moved.count; ++i) {
    nearest = std::min(nearest, point_distance_squared(a, moved.vertices[i]));
  }
  for (int i = 0; i < a.count && nearest > 0.0f; ++i) {
    nearest = std::min(nearest, point_distance_squared(moved, a.vertices[i]));
  }
  if (nearest > 0.0f && a.count > 1 && moved.count > 1) {
    for (int i = 0; i < a.count; ++i) {
      const vec2 a0 = a.vertices[i];
      const vec2 a1 = a.vertices[(i + 1) % a.count];
      for (int k = 0; k < moved.count; ++k) {
        const vec2 b0 = moved.vertices[k];
        const vec2 b1 = moved.vertices[(k + 1) % moved.count];
        const bool b_straddles = (cross(a1 - a0, b0 - a0) < 0.0f) != (cross(a1 - a0, b1 - a0) < 0.0f);
        const bool a_straddles = (cross(b1 - b0, a0 - b0) < 0.0f) != (cross(b1 - b0, a1 - b0) < 0.0f);
        if (a_straddles && b_straddles) return 0.0f;
      }
    }
  }
  return std::sqrt(nearest);
}

}  // namespace

PredictedMotion predict_motion(const Body& body, const WorldSettings& settings, float h) {
  PredictedMotion motion;
  if (body.type == BodyType::Static || !body.awake) return motion;
  motion.velocity = body.linear_velocity;
  if (body.type == BodyType::Dynamic) {
    motion.velocity += (body.force * body.inverse_mass + settings.gravity * body.gravity_scale) * h;
  }
  // Discs turn in place and boxes never turn: only a polygon's corners and a capsule's or
  // segment's ends sweep.
  if (settings.enable_rotation && body.compound) {
    motion.turn_reach = std::fabs(body.angular_velocity) * body.extent * h;
  } else if (settings.enable_rotation && body.shape.type() != ShapeType::Circle &&
             body.shape.type() != ShapeType::Box) {
    motion.turn_reach = std::fabs(body.angular_velocity) * rotation_reach(body.shape) * h;
  }
  return motion;
}

float closest_approach(const Shape& shape_a, const Transform& transform_a,
                       const PredictedMotion& motion_a, const Shape& shape_b,
                       const Transform& transform_b, const PredictedMotion& motion_b, float h,
                       float enough) {
  const vec2 origin = transform_a.position;
  const RoundedOutline outline_a = outline_of(shape_a, transform_a, origin);
  const RoundedOutline outline_b = outline_of(shape_b, transform_b, origin);
  const float radii = outline_a.radius + outline_b.radius;
  const vec2 relative_velocity = motion_b.velocity - motion_a.velocity;
  auto distance_at = [&](float t) {
    return std::max(outline_distance(outline_a, outline_b, relative_velocity * t) - radii, 0.0f);
  };
  // The ends first: a landing body meets the ground by the end of the step.
  float best = distance_at(h);
  if (best <= enough) return best;
  best = std::min(best, distance_at(0.0f));
  if (best <= enough) return best;
  // Convex in t: a golden-section search keeps the bracket that holds the minimum. 48
  // shrinkings by 0.618 leave a bracket of 1e-10 h, far below a float's resolution of t.
  constexpr float inverse_golden = 0.6180339887f;
  float low = 0.0f;
  float high = h;
  float left = high - inverse_golden * (high - low);
  float right = low + inverse_golden * (high - low);
  float at_left = distance_at(left);
  float at_right = distance_at(right);
  best = std::min(best, std::min(at_left, at_right));
  for (int i = 0; i < 48 && best > enough; ++i) {
    if (at_left <= at_right) {
      high = right;
      right = left;
      at_right = at_left;
      left = high - inverse_golden * (high - low);
      at_left = distance_at(left);
      best = std::min(best, at_left);
    } else {
      low = left;
      left = right;
      at_left = at_right;
      right = low + inverse_golden * (high - low);
      at_right = distance_at(right);
      best = std::min(best, at_right);
    }
  }
  return best;
}

bool is_ghost_contact(const Body& a, const PredictedMotion& motion_a, const Body& b,
                      const PredictedMotion& motion_b, const Contact& contact, float h) {
  bool closes_within_step = false;
  for (int i = 0; i < contact.point_count; ++i) {
    const ContactPoint& point = contact.points[i];
    if (point.depth >= 0.0f) return false;  // touching or overlapping: a real contact
    const vec2 velocity_b = motion_b.velocity + cross(b.angular_velocity, point.point - b.transform.position);
    const vec2 velocity_a = motion_a.velocity + cross(a.angular_velocity, point.point - a.transform.position);
    const float approach_speed = -glm::dot(velocity_b - velocity_a, contact.normal);
    closes_within_step = closes_within_step || approach_speed * h >= -point.depth;
  }
  if (!closes_within_step) return false;
  const float reach = motion_a.turn_reach + motion_b.turn_reach;
  return closest_approach(shape_of(a, contact.child_a), shape_transform(a, contact.child_a), motion_a,
                          shape_of(b, contact.child_b), shape_transform(b, contact.child_b), motion_b,
                          h, reach) > reach;
}

}  // namespace impulse2d

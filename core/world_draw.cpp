// World::draw: shapes at interpolated poses, then each overlay that is switched on.
#include "core/world.h"

#include "core/solver/world_state.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse2d {

// The joints overlay (core/world_draw_joints.cpp).
void draw_world_joints(const WorldState& state, DebugDraw& draw, const DebugDrawOptions& options);

namespace {

Color fill_of(const Body& body, const DebugDrawOptions& options) {
  const DebugPalette& palette = options.palette;
  if (body.is_sensor) return palette.sensor_fill;
  if (body.type == BodyType::Static) return palette.static_fill;
  if (body.type == BodyType::Kinematic) return palette.kinematic_fill;
  if (!body.awake && (options.flags & draw_sleeping)) return palette.sleeping_fill;
  return palette.dynamic_fill;
}

// The pose to draw: previous * (1 - alpha) + current * alpha.
Transform drawn_transform(const Body& body, float alpha) {
  const vec2 position = body.previous_position * (1.0f - alpha) + body.transform.position * alpha;
  const float angle = body.previous_angle * (1.0f - alpha) + body.angle * alpha;
  return Transform{position, Rotation::from_angle(angle)};
}

/// Most points of a drawn rounded outline: 8 corners, each an arc of at most 16 steps plus its
/// start point.
constexpr int max_rounded_points = max_polygon_vertices * 17;

/// Fills `points` (world) with the outline of the convex `vertices` (body-local, CCW, 2..8;
/// two for a capsule) swollen by `radius` > 0: at each vertex an arc from the previous edge's
/// normal to the next one's, in steps of at most 15 degrees. Returns the point count.
int rounded_outline(const vec2* vertices, int count, float radius, const Transform& transform,
                    vec2* points) {
  constexpr float step_angle = 3.14159265358979f / 12.0f;
  vec2 normals[max_polygon_vertices];
  for (int i = 0; i < count; ++i) {
    normals[i] = glm::normalize(right_perpendicular(vertices[(i + 1) % count] - vertices[i]));
  }
  int written = 0;
  for (int i = 0; i < count; ++i) {
    const vec2 before = normals[(i + count - 1) % count];
    const vec2 after = normals[i];
    float sweep = std::atan2(cross(before, after), glm::dot(before, after));
    if (count == 2) sweep = 3.14159265358979f;  // a capsule's cap: a half turn
    const int steps = std::max(1, static_cast<int>(std::ceil(sweep / step_angle)));
    const float start = std::atan2(before.y, before.x);
    for (int k = 0; k <= steps; ++k) {
      const float angle = start + sweep * static_cast<float>(k) / static_cast<float>(steps);
      points[written++] =
          transform.apply(vertices[i] + radius * vec2(std::cos(angle), std::sin(angle)));
    }
  }
  return written;
}

void draw_shape(DebugDraw& draw, const Shape& shape, const Transform& transform, Color fill,
                Color outline) {
  switch (shape.type()) {
    case ShapeType::Circle:
      draw.draw_solid_circle(transform.position, shape.circle().radius, transform.rotation.x_axis(),
                             fill, outline);
      return;
    case ShapeType::Box: {
      const vec2 half = shape.box().half_extents;
      const vec2 p = transform.position;  // boxes never rotate
      const vec2 corners[4] = {p + vec2(-half.x, -half.y), p + vec2(half.x, -half.y),
                               p + vec2(half.x, half.y), p + vec2(-half.x, half.y)};
      draw.draw_solid_polygon(corners, 4, fill, outline);
      return;
    }
    case ShapeType::Polygon: {
      if (shape.polygon().rounding > 0.0f) {
        vec2 points[max_rounded_points];
        const int count = rounded_outline(shape.polygon().vertices.data(), shape.polygon().count,
                                          shape.polygon().rounding, transform, points);
        draw.draw_solid_polygon(points, count, fill, outline);
        draw.draw_segment(transform.position, transform.apply(shape.polygon().vertices[0]), outline);
        return;
      }
      vec2 corners[max_polygon_vertices];
      for (int i = 0; i < shape.polygon().count; ++i) corners[i] = transform.apply(shape.polygon().vertices[i]);
      draw.draw_solid_polygon(corners, shape.polygon().count, fill, outline);
      // Orientation mark: a line from the centroid to the first vertex.
      draw.draw_segment(transform.position, corners[0], outline);
      return;
    }
    case ShapeType::Capsule: {
      const Capsule& capsule = shape.capsule();
      const vec2 centres[2] = {capsule.center1, capsule.center2};
      vec2 points[max_rounded_points];
      const int count = rounded_outline(centres, 2, capsule.radius, transform, points);
      draw.draw_solid_polygon(points, count, fill, outline);
      // Orientation mark: the core segment between the cap centres.
      draw.draw_segment(transform.apply(capsule.center1), transform.apply(capsule.center2), outline);
      return;
    }
    case ShapeType::Segment:
      draw.draw_segment(transform.apply(shape.segment().point1),
                        transform.apply(shape.segment().point2), outline);
      return;
  }
}

void draw_box_outline(DebugDraw& draw, const Aabb& box, Color color) {
  const vec2 corners[4] = {box.lower, vec2(box.upper.x, box.lower.y), box.upper,
                           vec2(box.lower.x, box.upper.y)};
  for (int i = 0; i < 4; ++i) draw.draw_segment(corners[i], corners[(i + 1) % 4], color);
}

}  // namespace

void World::draw(DebugDraw& draw, const DebugDrawOptions& options) const {
  const std::uint32_t flags = options.flags;
  const DebugPalette& palette = options.palette;
  const float alpha = std::clamp(options.interpolation_alpha, 0.0f, 1.0f);

  if (flags & draw_shapes) {
    for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
      if (!state_->alive[i]) continue;
      const Body& body = state_->bodies[i];
      const Transform drawn = drawn_transform(body, alpha);
      for (int k = 0; k < shape_count_of(body); ++k) {
        const Color fill = is_sensor_shape(body, k) ? palette.sensor_fill : fill_of(body, options);
        draw_shape(draw, shape_of(body, k), shape_transform(body, k, drawn), fill, palette.outline);
      }
    }
  }
  if (flags & draw_contact_normals) {
    // Chain links' front sides: a short tick from each link's midpoint along its normal.
    for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
      const Body& body = state_->bodies[i];
      if (!state_->alive[i] || body.shape.type() != ShapeType::Segment ||
          !body.shape.segment().one_sided) {
        continue;
      }
      const Segment& link = body.shape.segment();
      const vec2 start = body.transform.apply(link.point1);
      const vec2 edge = body.transform.apply(link.point2) - start;
      const vec2 middle = start + 0.5f * edge;
      draw.draw_segment(middle,
                        middle + glm::normalize(left_perpendicular(edge)) * (0.5f * options.normal_length),
                        palette.outline);
    }
  }
  if (flags & draw_aabbs) {
    for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
      if (state_->alive[i]) draw_box_outline(draw, state_->bodies[i].aabb, palette.aabb);
    }
  }
  if (flags & draw_broad_phase) {
    for (const BodyPair& pair : state_->pairs) {
      if (!state_->alive[pair.first] || !state_->alive[pair.second]) continue;
      draw.draw_segment(state_->bodies[pair.first].transform.position, state_->bodies[pair.second].transform.position,
                        palette.broad_phase_pair);
    }
  }
  for (const Contact& contact : state_->contacts) {
    if (!contact.enabled) continue;
    const vec2 normal = contact.normal;
    const vec2 tangent = right_perpendicular(normal);
    for (int i = 0; i < contact.point_count; ++i) {
      const ContactPoint& point = contact.points[i];
      if (flags & draw_penetration) {
        const vec2 half = normal * (0.5f * point.depth * options.penetration_scale);
        draw.draw_segment(point.point - half, point.point + half, palette.penetration);
      }
      if (flags & draw_contact_normals) {
        draw.draw_arrow(point.point, point.point + normal * options.normal_length, palette.contact_normal);
      }
      if ((flags & draw_normal_impulses) && point.normal_impulse > 0.0f) {
        draw.draw_arrow(point.point, point.point + normal * (point.normal_impulse * options.impulse_scale),
                        palette.normal_impulse);
      }
      if ((flags & draw_friction_impulses) && point.tangent_impulse != 0.0f) {
        draw.draw_arrow(point.point, point.point + tangent * (point.tangent_impulse * options.impulse_scale),
                        palette.friction_impulse);
      }
      if (flags & draw_contact_points) draw.draw_point(point.point, 6.0f, palette.contact_point);
    }
  }
  for (std::size_t i = 0; i < state_->bodies.size(); ++i) {
    if (!state_->alive[i]) continue;
    const Body& body = state_->bodies[i];
    const vec2 center = drawn_transform(body, alpha).position;
    if ((flags & draw_velocities) && body.type != BodyType::Static &&
        length_squared(body.linear_velocity) > 0.0f) {
      draw.draw_arrow(center, center + body.linear_velocity * options.velocity_scale, palette.velocity);
    }
    if (flags & draw_center_of_mass) draw.draw_point(center, 5.0f, palette.center_of_mass);
    if (flags & draw_body_ids) draw.draw_text(center, std::to_string(i), palette.label);
  }
  if (flags & draw_joints) draw_world_joints(*state_, draw, options);
}

}  // namespace impulse2d

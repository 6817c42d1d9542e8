#pragma once
/// @file body_state.h
/// The state the world keeps for one body (internal: users read a `BodyView`).

#include "core/body.h"

#include <cstddef>
#include <vector>

namespace impulse2d {

/// The state the world keeps for one body. Users read it through `World::body(id)`.
/// The fields that the narrow phase and contact preparation read for every contact come
/// first, the material's coefficients included, so that they fill the first two cache lines
/// (128 bytes on x86-64 with GCC's std::string: `body_contact_bytes`); the rest (sleep,
/// interpolation, events, the shape's geometry) after them.
struct Body {
  BodyId id;                  ///< this body's handle
  BodyType type = BodyType::Dynamic;  ///< how it moves
  bool awake = true;             ///< false while sleeping
  bool fixed_rotation = false;   ///< inertia treated as infinite
  bool is_bullet = false;        ///< swept against other bodies each step (no tunnelling)
  Transform transform;        ///< position (centre of mass) and rotation
  float angle = 0.0f;         ///< radians, unwrapped (keeps counting past pi)
  vec2 linear_velocity{0.0f, 0.0f};  ///< m/s
  float angular_velocity = 0.0f;     ///< rad/s
  float inverse_mass = 0.0f;     ///< 1/kg
  float inverse_inertia = 0.0f;  ///< 1/(kg m^2); 0 when rotation is fixed
  vec2 force{0.0f, 0.0f};  ///< N, accumulated until the next step, then cleared
  float torque = 0.0f;     ///< N m, accumulated until the next step, then cleared
  float gravity_scale = 1.0f;    ///< multiplies the world's gravity
  /// Farthest distance (m) of the shape's surface from the centre of mass (`shape_extent`),
  /// kept here beside the fields contact recycling reads, away from the shape's cold bytes.
  float extent = 0.0f;
  /// `shape_rounding` of the shape (m): how far its surface lies outside its core, read when
  /// each contact is prepared.
  float rounding = 0.0f;
  bool compound = false;         ///< its shapes are `children` (and not `shape`)
  bool speculative = true;       ///< its pairs get speculative contacts
  Material material;          ///< what it is made of (its coefficients mixed for each contact)
  float linear_damping = 0.0f;   ///< 1/s
  float angular_damping = 0.0f;  ///< 1/s
  float mass = 0.0f;             ///< kg (0 for static and kinematic bodies)
  float inertia = 0.0f;          ///< kg m^2 about the centre of mass
  vec2 previous_position{0.0f, 0.0f};  ///< at the start of the last step (for interpolation)
  float previous_angle = 0.0f;          ///< at the start of the last step
  float sleep_time = 0.0f;       ///< seconds the body has been slow
  std::uint32_t collision_layers = 1;  ///< bitmask
  Aabb aabb;                     ///< world bounds, updated each step
  std::uint64_t user_data = 0;   ///< the caller's value
  bool enable_contact_events = true;  ///< report begin/end touch of its pairs
  bool enable_hit_events = false;     ///< report its pairs' impacts
  bool is_sensor = false;             ///< no contacts; reports overlaps instead
  bool sensor_detects_static = false; ///< as a sensor: also reports static bodies
  bool enable_sensor_events = true;   ///< sensors see it
  bool has_sensor_shapes = false;     ///< a compound body with a sensor among its shapes
  /// In body-local coordinates, centroid at the origin; a compound body's first shape (for
  /// the rules that look at one shape's kind: never its geometry, which `children` holds).
  Shape shape;
  /// A compound body's shapes, placed in the body's frame; empty for a body of one shape.
  std::vector<BodyShape> children;
};

/// The bytes at the start of a `Body` that the narrow phase and contact preparation read for a
/// kept contact (all but its shape's geometry): two cache lines where the layout allows.
constexpr std::size_t body_contact_bytes = offsetof(Body, linear_damping);

/// `body`'s core point (body frame, metres) under its surface point `surface` (world metres),
/// where `outward` (unit, world) is the surface's normal there: a circle's centre (exactly
/// the origin), else the surface point moved in by the body's rounding. For a compound body,
/// that of its shape `child`.
inline vec2 core_anchor(const Body& body, int child, vec2 surface, vec2 outward) {
  if (body.compound) {
    const BodyShape& part = body.children[static_cast<std::size_t>(child)];
    if (part.shape.type() == ShapeType::Circle) return part.local.position;
    return body.transform.apply_inverse(surface - outward * shape_rounding(part.shape));
  }
  if (body.shape.type() == ShapeType::Circle) return vec2(0.0f, 0.0f);
  return body.transform.apply_inverse(surface - outward * body.rounding);
}

/// True when `body`'s shape `child` (its one shape when not compound) is a circle.
inline bool is_circle(const Body& body, int child) {
  return (body.compound ? body.children[static_cast<std::size_t>(child)].shape : body.shape).type() ==
         ShapeType::Circle;
}

/// Where the centre of `body`'s shape `child` lies in the body's frame (metres): the origin
/// unless the body is compound.
inline vec2 local_centre(const Body& body, int child) {
  return body.compound ? body.children[static_cast<std::size_t>(child)].local.position : vec2(0.0f, 0.0f);
}

/// How far (m) the surface of `body`'s shape `child` (its one shape when not compound) lies
/// outside its core (`shape_rounding`).
inline float rounding_of(const Body& body, int child) {
  return body.compound ? shape_rounding(body.children[static_cast<std::size_t>(child)].shape)
                       : body.rounding;
}

/// The view of `body` that `World::body` hands out.
inline BodyView view_of(const Body& body) {
  BodyView view;
  view.id = body.id;
  view.type = body.type;
  view.awake = body.awake;
  view.fixed_rotation = body.fixed_rotation;
  view.is_bullet = body.is_bullet;
  view.transform = body.transform;
  view.angle = body.angle;
  view.linear_velocity = body.linear_velocity;
  view.angular_velocity = body.angular_velocity;
  view.previous_position = body.previous_position;
  view.previous_angle = body.previous_angle;
  view.mass = body.mass;
  view.inertia = body.inertia;
  view.inverse_inertia = body.inverse_inertia;
  view.gravity_scale = body.gravity_scale;
  view.linear_damping = body.linear_damping;
  view.angular_damping = body.angular_damping;
  view.collision_layers = body.collision_layers;
  view.aabb = body.aabb;
  view.user_data = body.user_data;
  view.shape = &body.shape;
  if (body.compound) {
    view.shapes = body.children.data();
    view.shape_count = static_cast<int>(body.children.size());
  }
  view.material = &body.material;
  view.is_sensor = body.is_sensor;
  return view;
}

}  // namespace impulse2d

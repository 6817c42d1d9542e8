#pragma once
/// @file body.h
/// Rigid bodies: their definition, their handle, and the state the world keeps for each.

#include "core/material.h"
#include "core/math.h"
#include "core/shape.h"

#include <cstdint>

namespace impulse2d {

/// How a body moves.
enum class BodyType : std::uint8_t {
  Static,     ///< never moves; infinite mass
  Kinematic,  ///< moves by its velocity only; infinite mass; pushes dynamic bodies
  Dynamic,    ///< moved by gravity, forces and contacts
};

/// A handle to a body: index into the world's slots plus the slot's generation. A handle whose
/// body was removed is stale; using it throws `Error` instead of touching another body.
struct BodyId {
  std::uint32_t index = 0xFFFFFFFFu;  ///< slot index
  std::uint32_t generation = 0;       ///< slot generation when the body was created
  /// True for a handle that was never assigned.
  bool is_null() const { return index == 0xFFFFFFFFu; }
  /// Handles are equal when they name the same slot and generation.
  bool operator==(const BodyId& other) const {
    return index == other.index && generation == other.generation;
  }
  /// Opposite of ==.
  bool operator!=(const BodyId& other) const { return !(*this == other); }
};

/// Everything needed to create a body. Start from the defaults and change what you need.
struct BodyDef {
  BodyType type = BodyType::Dynamic;     ///< static, kinematic or dynamic
  vec2 position{0.0f, 0.0f};             ///< centre of mass in the world, metres
  float angle = 0.0f;                    ///< radians, counter-clockwise
  vec2 linear_velocity{0.0f, 0.0f};      ///< m/s
  float angular_velocity = 0.0f;         ///< rad/s, counter-clockwise
  float gravity_scale = 1.0f;            ///< multiplies the world's gravity for this body
  float linear_damping = 0.0f;           ///< 1/s; v *= 1 / (1 + dt * damping) each step
  float angular_damping = 0.0f;          ///< 1/s; w *= 1 / (1 + dt * damping) each step
  bool fixed_rotation = false;           ///< infinite inertia: contacts never spin it
  bool is_bullet = false;                ///< swept against other bodies each step (no tunnelling)
  /// Speculative contacts for this body's pairs (see `WorldSettings::speculative_margin`);
  /// false: its contacts exist only while overlapping (as a controller that senses contacts
  /// by overlap expects).
  bool speculative = true;
  std::uint32_t collision_layers = 1;    ///< collides with bodies whose layers share a bit
  Material material = materials::wood(); ///< density, restitution, friction
  std::uint64_t user_data = 0;           ///< any value the caller wants back
};

/// The state the world keeps for one body. Read it through `World::body(id)`.
/// The fields the step reads for every contact and sub-step come first, so that they share
/// the first two cache lines; the shape and material (read by the narrow phase alone) last.
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
  float linear_damping = 0.0f;   ///< 1/s
  float angular_damping = 0.0f;  ///< 1/s
  float mass = 0.0f;             ///< kg (0 for static and kinematic bodies)
  float inertia = 0.0f;          ///< kg m^2 about the centre of mass
  vec2 previous_position{0.0f, 0.0f};  ///< at the start of the last step (for interpolation)
  float previous_angle = 0.0f;          ///< at the start of the last step
  float sleep_time = 0.0f;       ///< seconds the body has been slow
  /// Farthest distance (m) of the shape's surface from the centre of mass (`shape_extent`),
  /// kept here beside the fields contact recycling reads, away from the shape's cold bytes.
  float extent = 0.0f;
  bool speculative = true;       ///< its pairs get speculative contacts
  std::uint32_t collision_layers = 1;  ///< bitmask
  Aabb aabb;                     ///< world bounds, updated each step
  std::uint64_t user_data = 0;   ///< the caller's value
  Material material;          ///< what it is made of
  Shape shape;                ///< in body-local coordinates, centroid at the origin
};

}  // namespace impulse2d

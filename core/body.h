#pragma once
/// @file body.h
/// Rigid bodies: their definition, their handle, and the view of one that the world hands out.

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
  /// Report this body's contacts' begin and end of touch (`World::contact_events`); a pair
  /// reports when either body asks (Box2D v3: on by default).
  bool enable_contact_events = true;
  /// Report impacts faster than `World::hit_event_threshold()` (`ContactEvents::hit`); a pair
  /// reports when either body asks (off by default, as Box2D v3).
  bool enable_hit_events = false;
  /// A sensor: no collision response at all (no contacts, bullets pass), but it reports every
  /// non-sensor body whose collision layers share a bit with its own that begins or stops
  /// overlapping it (`World::sensor_events`).
  bool is_sensor = false;
  /// For a sensor (or a body with sensor shapes): also report static bodies (off by default).
  bool sensor_detects_static = false;
  /// Sensors see this body (on by default; a sensor itself is never seen).
  bool enable_sensor_events = true;
};

/// One shape of a body made of several (a compound body), as the caller gives it: the shape in
/// its own frame (as `make_circle`, `make_polygon`, ... return it) and where that frame lies in
/// the body's, with its own material and collision layers.
struct ShapeDef {
  Shape shape;                        ///< in its own frame
  vec2 position{0.0f, 0.0f};          ///< its frame's origin in the body's frame, metres
  float angle = 0.0f;                 ///< its frame's turn in the body's frame, radians
  Material material = materials::wood();  ///< density (mass), friction and restitution
  std::uint32_t collision_layers = 1; ///< collides with shapes whose layers share a bit
  /// A sensor shape: no contacts, but it reports the shapes of other bodies that begin or stop
  /// overlapping it (`World::sensor_events`, as a sensor body does); it still has mass.
  bool is_sensor = false;
};

/// Most shapes one body may have.
constexpr int max_body_shapes = 256;

/// One shape of a compound body as the world keeps it: placed in the body's frame, whose
/// origin is the body's centre of mass (`World::create_body` with several shapes re-centres).
struct BodyShape {
  Shape shape;                        ///< in its own frame (a `Box` given is kept as a polygon)
  Transform local;                    ///< its frame in the body's: metres and rotation
  Material material;                  ///< what it is made of
  std::uint32_t collision_layers = 1; ///< bitmask
  bool is_sensor = false;             ///< senses overlaps, never collides
};

/// What users read of a body, returned by `World::body(id)`: a copy of its state taken when
/// asked (it does not follow the body as the world steps), plus pointers to its shape and
/// material, which stay in the world and are valid until the world next creates or removes a
/// body. Change a body through `World`'s setters.
struct BodyView {
  BodyId id;                          ///< this body's handle
  BodyType type = BodyType::Dynamic;  ///< how it moves
  bool awake = true;                  ///< false while sleeping
  bool fixed_rotation = false;        ///< inertia treated as infinite
  bool is_bullet = false;             ///< swept against other bodies each step (no tunnelling)
  Transform transform;                ///< position of the centre of mass (metres) and rotation
  float angle = 0.0f;                 ///< radians, unwrapped (keeps counting past pi)
  vec2 linear_velocity{0.0f, 0.0f};   ///< m/s
  float angular_velocity = 0.0f;      ///< rad/s, counter-clockwise
  /// Centre of mass at the start of the last step, metres: draw at
  /// `previous_position + (transform.position - previous_position) * World::interpolation_alpha()`.
  vec2 previous_position{0.0f, 0.0f};
  float previous_angle = 0.0f;        ///< radians, at the start of the last step
  float mass = 0.0f;                  ///< kg (0 for static and kinematic bodies)
  float inertia = 0.0f;               ///< kg m^2 about the centre of mass
  float inverse_inertia = 0.0f;       ///< 1/(kg m^2); 0 when contacts cannot turn it
  float gravity_scale = 1.0f;         ///< multiplies the world's gravity
  float linear_damping = 0.0f;        ///< 1/s
  float angular_damping = 0.0f;       ///< 1/s
  std::uint32_t collision_layers = 1; ///< bitmask
  Aabb aabb;                          ///< world bounds after the last step, metres
  std::uint64_t user_data = 0;        ///< the caller's value
  /// The body's one shape, in body-local coordinates with its centroid at the origin; for a
  /// compound body (`shape_count > 0`) its first shape, in that shape's own frame.
  const Shape* shape = nullptr;
  /// A compound body's shapes (null for a body of one shape), `shape_count` of them.
  const BodyShape* shapes = nullptr;
  int shape_count = 0;                ///< number of `shapes`; 0 for a body of one shape
  const Material* material = nullptr; ///< what it is made of
  bool is_sensor = false;             ///< detects overlaps, never collides
};

}  // namespace impulse2d

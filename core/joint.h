#pragma once
/// @file joint.h
/// Joints between two bodies: their handle and one definition per type, each with Box2D v3's
/// defaults (`b2DefaultRevoluteJointDef` and friends are the default member values here).
/// Anchors are in each body's local frame, measured from its centre of mass (the body's
/// position), in metres. Create and destroy joints through `World`.

#include "core/body.h"
#include "core/math.h"

#include <cstdint>

namespace impulse2d {

/// The kinds of joint.
enum class JointType : std::uint8_t {
  Revolute,   ///< a shared point; the bodies turn about it (hinge)
  Prismatic,  ///< slides along an axis fixed in body A; no relative turning
  Distance,   ///< keeps two anchors at a length, or between a min and a max (rope), or on a spring
  Weld,       ///< glues two bodies, rigidly or through linear and angular springs
  Wheel,      ///< point on a line of body A with a suspension spring along it; B turns freely
  Motor,      ///< drives B's pose relative to A towards an offset with bounded force and torque
  Mouse,      ///< pulls a point of body B towards a world target on a spring (body A only anchors)
};

/// A handle to a joint: slot index plus the slot's generation. A handle whose joint was
/// destroyed (directly or with one of its bodies) is stale; using it throws `Error`.
struct JointId {
  std::uint32_t index = 0xFFFFFFFFu;  ///< slot index
  std::uint32_t generation = 0;       ///< slot generation when the joint was created
  /// True for a handle that was never assigned.
  bool is_null() const { return index == 0xFFFFFFFFu; }
  /// Handles are equal when they name the same slot and generation.
  bool operator==(const JointId& other) const {
    return index == other.index && generation == other.generation;
  }
  /// Opposite of ==.
  bool operator!=(const JointId& other) const { return !(*this == other); }
};

/// A hinge: `local_anchor_a` on A and `local_anchor_b` on B are kept at one point. The joint
/// angle is angle_B - angle_A - reference_angle (radians, unwrapped: it keeps counting past pi).
struct RevoluteJointDef {
  BodyId body_a;                        ///< first body
  BodyId body_b;                        ///< second body
  vec2 local_anchor_a{0.0f, 0.0f};      ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  float reference_angle = 0.0f;         ///< radians: angle_B - angle_A at joint angle 0
  bool enable_spring = false;           ///< a rotational spring towards joint angle 0
  float hertz = 0.0f;                   ///< spring frequency, Hz (0: no stiffness)
  float damping_ratio = 0.0f;           ///< spring damping ratio (1 = critical)
  bool enable_limit = false;            ///< keep the joint angle within [lower, upper]
  float lower_angle = 0.0f;             ///< radians
  float upper_angle = 0.0f;             ///< radians
  bool enable_motor = false;            ///< drive the relative angular speed
  float motor_speed = 0.0f;             ///< rad/s, counter-clockwise of B relative to A
  float max_motor_torque = 0.0f;        ///< N m, the most the motor may apply
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// A slider: B's anchor moves only along `local_axis_a` (fixed in A) through A's anchor, and the
/// bodies keep their relative angle. Translation = (anchor_B - anchor_A) . axis, metres.
struct PrismaticJointDef {
  BodyId body_a;                        ///< first body
  BodyId body_b;                        ///< second body
  vec2 local_anchor_a{0.0f, 0.0f};      ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  vec2 local_axis_a{1.0f, 0.0f};        ///< direction of travel in A's frame (normalised on creation)
  float reference_angle = 0.0f;         ///< radians: the angle_B - angle_A that is kept
  bool enable_spring = false;           ///< a spring along the axis towards translation 0
  float hertz = 0.0f;                   ///< spring frequency, Hz
  float damping_ratio = 0.0f;           ///< spring damping ratio
  bool enable_limit = false;            ///< keep the translation within [lower, upper]
  float lower_translation = 0.0f;       ///< metres
  float upper_translation = 0.0f;       ///< metres
  bool enable_motor = false;            ///< drive the speed along the axis
  float motor_speed = 0.0f;             ///< m/s of B relative to A along the axis
  float max_motor_force = 0.0f;         ///< N, the most the motor may apply
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// Keeps the distance between two anchors at `length` (rigid), or lets it vary within
/// [min_length, max_length] (`enable_limit`), on a spring around `length` (`enable_spring`,
/// hertz > 0) or free (`enable_spring` with hertz 0). A rope of length L: enable_spring with
/// hertz 0, enable_limit, min_length 0, max_length L.
struct DistanceJointDef {
  BodyId body_a;                        ///< first body
  BodyId body_b;                        ///< second body
  vec2 local_anchor_a{0.0f, 0.0f};      ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  float length = 1.0f;                  ///< rest length, metres (>= 0.005)
  bool enable_spring = false;           ///< false: the length is held rigidly
  float hertz = 0.0f;                   ///< spring frequency, Hz (0: no spring force)
  float damping_ratio = 0.0f;           ///< spring damping ratio
  bool enable_limit = false;            ///< keep the length within [min_length, max_length]
  float min_length = 0.0f;              ///< metres
  float max_length = 100000.0f;         ///< metres
  bool enable_motor = false;            ///< drive the speed of lengthening
  float motor_speed = 0.0f;             ///< m/s
  float max_motor_force = 0.0f;         ///< N
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// Glues B to A at the anchors with the relative angle `reference_angle`: rigid when a hertz
/// is 0, else a spring of that frequency for that part.
struct WeldJointDef {
  BodyId body_a;                        ///< first body
  BodyId body_b;                        ///< second body
  vec2 local_anchor_a{0.0f, 0.0f};      ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  float reference_angle = 0.0f;         ///< radians: the angle_B - angle_A that is kept
  float linear_hertz = 0.0f;            ///< Hz; 0: rigid
  float angular_hertz = 0.0f;           ///< Hz; 0: rigid
  float linear_damping_ratio = 1.0f;    ///< of the linear spring
  float angular_damping_ratio = 1.0f;   ///< of the angular spring
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// A wheel on a suspension: B's anchor stays on the line through A's anchor along
/// `local_axis_a`, held towards translation 0 by a spring; B turns freely (or by the motor).
struct WheelJointDef {
  BodyId body_a;                        ///< chassis
  BodyId body_b;                        ///< wheel
  vec2 local_anchor_a{0.0f, 0.0f};      ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  vec2 local_axis_a{0.0f, 1.0f};        ///< suspension axis in A's frame (normalised on creation)
  bool enable_spring = true;            ///< suspension spring on
  float hertz = 1.0f;                   ///< suspension frequency, Hz
  float damping_ratio = 0.7f;           ///< suspension damping ratio
  bool enable_limit = false;            ///< keep the translation within [lower, upper]
  float lower_translation = 0.0f;       ///< metres
  float upper_translation = 0.0f;       ///< metres
  bool enable_motor = false;            ///< drive the wheel's spin relative to A
  float motor_speed = 0.0f;             ///< rad/s
  float max_motor_torque = 0.0f;        ///< N m
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// Drives B's centre towards A's centre + A's rotation of `linear_offset`, and B's angle
/// towards angle_A + `angular_offset`, with at most `max_force` and `max_torque`.
struct MotorJointDef {
  BodyId body_a;                        ///< reference body
  BodyId body_b;                        ///< driven body
  vec2 linear_offset{0.0f, 0.0f};       ///< metres, in A's frame
  float angular_offset = 0.0f;          ///< radians
  float max_force = 1.0f;               ///< N
  float max_torque = 1.0f;              ///< N m
  float correction_factor = 0.3f;       ///< fraction of the pose error closed per time step, [0, 1]
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

/// Pulls `local_anchor_b` of B towards the world point `target` on a spring of at most
/// `max_force` (dragging with a mouse). Body A (usually a static ground) is not acted on.
struct MouseJointDef {
  BodyId body_a;                        ///< anchor body (not acted on)
  BodyId body_b;                        ///< the dragged body
  vec2 local_anchor_b{0.0f, 0.0f};      ///< metres, in B's frame from its centre of mass
  vec2 target{0.0f, 0.0f};              ///< world point, metres
  float hertz = 4.0f;                   ///< Hz
  float damping_ratio = 1.0f;           ///< spring damping ratio
  float max_force = 1.0f;               ///< N
  bool collide_connected = false;       ///< false: contacts between A and B are skipped
  std::uint64_t user_data = 0;          ///< any value the caller wants back
};

}  // namespace impulse2d

#pragma once
/// @file scene_event.h
/// Scripted events of a scene: things that happen just before a given step.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/body.h"
#include "core/shape.h"
#include "core/world.h"
#include "scene/scene_joint.h"

namespace impulse2d::demos {

/// A body to create: its definition and its shape (or shapes).
struct BodySpawn {
  BodyDef def;  ///< position, velocity, material, ...
  Shape shape;  ///< validated shape (make_circle, make_box, make_polygon, ...); a compound's first
  /// A compound body's shapes placed about `def.position` (empty: the body is `shape` alone).
  std::vector<ShapeDef> shapes;
};

/// Creates `spawn` in `world`: a body of one shape, or a compound body.
inline BodyId create_spawn(World& world, const BodySpawn& spawn) {
  if (spawn.shapes.empty()) return world.create_body(spawn.def, spawn.shape);
  return world.create_body(spawn.def, spawn.shapes.data(), static_cast<int>(spawn.shapes.size()));
}

/// What a scripted event does.
enum class SceneEventKind {
  Impulse,  ///< apply a linear (and angular) impulse to a body
  /// Apply a force (and torque) to a body before each of `steps` consecutive steps: the world
  /// integrates it every sub-step, a smooth push where an impulse is a kick.
  Force,
  Spawn,    ///< create a body
  Remove,   ///< remove a body
  Button,   ///< press or release a named button of the scene's controls
  CreateJoint,   ///< create a joint (`joint`) between bodies that exist by then
  DestroyJoint,  ///< destroy the joint named `joint_name`
  MouseTarget,   ///< move the target of the mouse joint named `joint_name` to `target`
};

/// One scripted event. Bodies are named by their creation index in the run: the builder's
/// bodies first, in the order they were created, then each spawned body as it appears.
struct SceneEvent {
  std::int64_t step = 0;  ///< applied just before this step is taken (0: before the first)
  SceneEventKind kind = SceneEventKind::Impulse;  ///< what happens
  int body = -1;  ///< Impulse, Force, Remove: creation index of the body
  vec2 impulse{0.0f, 0.0f};                       ///< Impulse: linear impulse, N s
  /// Impulse, Force: world point, metres (none: centre of mass). A force's point is where it
  /// acts at its first step; it moves with the body after that.
  std::optional<vec2> point;
  float angular_impulse = 0.0f;  ///< Impulse: angular impulse, N m s
  vec2 force{0.0f, 0.0f};        ///< Force: force, N
  float torque = 0.0f;           ///< Force: torque, N m
  std::int64_t steps = 1;        ///< Force: consecutive steps it acts for, from `step` (>= 1)
  BodySpawn spawn;               ///< Spawn: the body to create
  std::string button;            ///< Button: its name, e.g. "jump"
  bool pressed = true;           ///< Button: true = pressed, false = released
  JointSpec joint;               ///< CreateJoint: the joint to create (it may have a name)
  std::string joint_name;        ///< DestroyJoint, MouseTarget: the joint's name
  vec2 target{0.0f, 0.0f};       ///< MouseTarget: new world target, metres
  std::string origin;            ///< where it was declared, for messages ("events[2]")
};

/// Why an impulse or force event on a body of `type` (static or kinematic) is rejected: the
/// world moves only dynamic bodies by them, so it would silently do nothing. `body` names it,
/// e.g. "body 0 (\"ground\")". Gives "body 0 (\"ground\") is static: an impulse cannot move it".
inline std::string unmovable_body_reason(const std::string& body, BodyType type,
                                         SceneEventKind kind) {
  const char* what = kind == SceneEventKind::Force ? "a force" : "an impulse";
  const char* type_name = type == BodyType::Static ? "static" : "kinematic";
  std::string reason = body + " is " + type_name + ": " + what + " cannot move it";
  if (type == BodyType::Kinematic) reason += " (a kinematic body moves only at its set velocity)";
  return reason;
}

}  // namespace impulse2d::demos

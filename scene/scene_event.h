#pragma once
/// @file scene_event.h
/// Scripted events of a scene: things that happen just before a given step.

#include <cstdint>
#include <optional>
#include <string>

#include "core/body.h"
#include "core/shape.h"

namespace impulse2d::demos {

/// A body to create: its definition and its shape.
struct BodySpawn {
  BodyDef def;  ///< position, velocity, material, ...
  Shape shape;  ///< validated shape (make_circle, make_box, make_polygon, ...)
};

/// What a scripted event does.
enum class SceneEventKind {
  Impulse,  ///< apply a linear (and angular) impulse to a body
  Spawn,    ///< create a body
  Remove,   ///< remove a body
  Button,   ///< press or release a named button of the scene's controls
};

/// One scripted event. Bodies are named by their creation index in the run: the builder's
/// bodies first, in the order they were created, then each spawned body as it appears.
struct SceneEvent {
  std::int64_t step = 0;  ///< applied just before this step is taken (0: before the first)
  SceneEventKind kind = SceneEventKind::Impulse;  ///< what happens
  int body = -1;                                  ///< Impulse, Remove: creation index of the body
  vec2 impulse{0.0f, 0.0f};                       ///< Impulse: linear impulse, N s
  std::optional<vec2> point;     ///< Impulse: world point, metres (none: centre of mass)
  float angular_impulse = 0.0f;  ///< Impulse: angular impulse, N m s
  BodySpawn spawn;               ///< Spawn: the body to create
  std::string button;            ///< Button: its name, e.g. "jump"
  bool pressed = true;           ///< Button: true = pressed, false = released
  std::string origin;            ///< where it was declared, for messages ("events[2]")
};

}  // namespace impulse2d::demos

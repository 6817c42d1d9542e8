#pragma once
/// @file events.h
/// What happened during a step, collected into buffers the caller reads after `World::step`
/// (no callbacks from inside the solver): contacts that began and stopped touching, hits
/// (impacts faster than a threshold) and sensor overlaps. Box2D v3's `b2ContactEvents` and
/// `b2SensorEvents` are the model.
///
/// Every list is in a deterministic order: by (A's slot, B's slot) for contacts, (sensor's
/// slot, visitor's slot) for sensors. End events of pairs whose body was removed between two
/// steps come first in the next step's end lists. The buffers are cleared at the start of each
/// step (they hold the last step's events) and reused, so reading them allocates nothing.

#include "core/body.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// A shape: its body and its index on the body (0 for a body of one shape; for a compound
/// body, its place in the list given to `World::create_body`).
struct ShapeId {
  BodyId body;              ///< the body the shape belongs to
  std::uint32_t index = 0;  ///< the shape's index on its body
  /// Shapes are equal when they are the same shape of the same body.
  bool operator==(const ShapeId& other) const { return body == other.body && index == other.index; }
  /// Opposite of ==.
  bool operator!=(const ShapeId& other) const { return !(*this == other); }
};

/// Two shapes began touching in the last step. A pair touches in a step when one of its contact
/// points, moving freely through the step (the velocities the bodies carried into it plus the
/// step's gravity and forces) from the gap it had when the step began, would end it closer than
/// `WorldSettings::slop` (or overlapping): resting, overlapping, or a speculative point the
/// bodies close within the step (the solver then stops them at the surface). So the step of
/// an impact is the step of its begin (or the next one, when the free motion ends the begin's
/// step just short of the surface, within the slop), and a bounce ends the touch the step it
/// leaves. A body
/// falling asleep keeps its touches; a contact turned off by the contact filter does not touch.
struct ContactBeginTouchEvent {
  ShapeId shape_a;  ///< shape of the body with the smaller slot
  ShapeId shape_b;  ///< the other shape
  BodyId body_a;    ///< A's body
  BodyId body_b;    ///< B's body
};

/// Two shapes stopped touching in the last step, or one of their bodies was removed (then the
/// removed body's handle is already stale).
struct ContactEndTouchEvent {
  ShapeId shape_a;  ///< shape of the body with the smaller slot
  ShapeId shape_b;  ///< the other shape
  BodyId body_a;    ///< A's body
  BodyId body_b;    ///< B's body
};

/// An impact: a pair whose bodies approach faster than `World::hit_event_threshold()` along the
/// contact normal at a point the step must stop, one that moving freely from its gap would end
/// the step inside the other body (Box2D v3 asks for a normal impulse at the point). A point
/// that only closes its gap in a step (the speculative contact lets it reach the surface) is hit
/// in the next step, where it is stopped, once; a corner still in the air while another point
/// of the pair rests is not hit until it lands. A contact that keeps being driven in faster
/// than the threshold is hit again, as in Box2D.
struct ContactHitEvent {
  ShapeId shape_a;          ///< shape of the body with the smaller slot
  ShapeId shape_b;          ///< the other shape
  BodyId body_a;            ///< A's body
  BodyId body_b;            ///< B's body
  vec2 point{0.0f, 0.0f};   ///< world point of the fastest approaching contact point, metres
  vec2 normal{0.0f, 0.0f};  ///< unit contact normal, from A to B
  /// Pre-solve approach speed along the normal at `point`, m/s (> 0): the relative normal
  /// velocity the bodies carried into the step plus what the step's gravity and applied forces
  /// add to it (damping left out), before any contact impulse: the speed they arrive with.
  float approach_speed = 0.0f;
};

/// The last step's contact events.
struct ContactEvents {
  std::vector<ContactBeginTouchEvent> begin;  ///< pairs that began touching, by pair
  std::vector<ContactEndTouchEvent> end;      ///< pairs that stopped touching, by pair
  std::vector<ContactHitEvent> hit;           ///< impacts, by pair
};

/// A shape began to overlap a sensor (tested on the positions at the end of the step).
struct SensorBeginTouchEvent {
  ShapeId sensor_shape;   ///< the sensor
  ShapeId visitor_shape;  ///< the shape that entered it
  BodyId sensor_body;     ///< the sensor's body
  BodyId visitor_body;    ///< the visitor's body
};

/// A shape stopped overlapping a sensor, or one of the two was removed.
struct SensorEndTouchEvent {
  ShapeId sensor_shape;   ///< the sensor
  ShapeId visitor_shape;  ///< the shape that left it
  BodyId sensor_body;     ///< the sensor's body
  BodyId visitor_body;    ///< the visitor's body
};

/// The last step's sensor events.
struct SensorEvents {
  std::vector<SensorBeginTouchEvent> begin;  ///< by (sensor slot, visitor slot)
  std::vector<SensorEndTouchEvent> end;      ///< by (sensor slot, visitor slot)
};

}  // namespace impulse2d

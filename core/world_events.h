#pragma once
/// @file world_events.h
/// The world's event bookkeeping (internal): what touched after the last step, what each
/// sensor held, the buffers the caller reads, and the stages that fill them after a step.

#include "core/events.h"
#include "core/math.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace impulse2d {

struct WorldState;
class WorkerPool;
struct FreeVelocities;

/// Two shapes of a remembered touch or overlap, ordered by slot (sensor first for sensors),
/// then by shape (for compound bodies).
struct EventPair {
  BodyId a;  ///< smaller slot (or the sensor)
  BodyId b;  ///< larger slot (or the visitor)
  std::uint16_t shape_a = 0;  ///< which of a's shapes (0 unless compound)
  std::uint16_t shape_b = 0;  ///< which of b's shapes (0 unless compound)
  /// Key for ordering: (a.index << 32 | b.index, shape_a << 16 | shape_b).
  std::pair<std::uint64_t, std::uint32_t> key() const {
    return {static_cast<std::uint64_t>(a.index) << 32 | b.index,
            static_cast<std::uint32_t>(shape_a) << 16 | shape_b};
  }
};

/// Event state of a world; copied with it and saved in snapshots.
struct WorldEvents {
  float hit_event_threshold = 1.0f;  ///< m/s (Box2D v3's default)
  int contact_event_bodies = 0;      ///< living bodies with enable_contact_events
  int hit_event_bodies = 0;          ///< living bodies with enable_hit_events
  int sensor_bodies = 0;             ///< living sensors

  std::vector<EventPair> touching;        ///< pairs touching after the last step, by key
  std::vector<EventPair> sensor_overlaps; ///< (sensor, visitor) after the last step, by key
  std::vector<EventPair> removed_touches; ///< ended by remove_body since the last step
  std::vector<EventPair> removed_overlaps;///< ended by remove_body since the last step

  /// True when `touching` is exactly the pairs of the awake contacts whose `touching` flag
  /// was set after the last step, with no contacts set aside (asleep) and every body asking
  /// for contact events: then a step whose touch tally (`WideContactSolver::TouchTally`)
  /// found no flag changed and as many touching contacts began and ended nothing, and the
  /// walk over the contacts is skipped. False after any other collect (and in a new world).
  bool touching_is_current = false;
  /// Steps whose contact events were found without the walk (for tests).
  std::uint64_t walks_skipped = 0;
  /// Tests: always walk the contacts (the events must be the same).
  bool always_walk = false;

  ContactEvents contact;  ///< the caller's buffers (last step's events)
  SensorEvents sensor;    ///< the caller's buffers (last step's events)

  // Scratch (reused; no allocation once warm).
  std::vector<EventPair> next;            ///< this step's touching / overlaps
  std::vector<vec2> free_linear_velocity; ///< per slot: start velocity + the step's forces
  std::vector<float> free_angular_velocity;  ///< per slot, rad/s
  std::vector<std::uint32_t> nearby;      ///< broad-phase query output
};

/// Start of a step: clears the caller's buffers (moving in the end events of removed bodies)
/// and, when contact or hit events are on, records each body's free velocity over the step
/// (on `pool`'s workers, when not null).
void begin_step_events(WorldState& world, WorkerPool* pool);
/// The free velocities `begin_step_events` recorded, for prepare to judge each awake contact's
/// touch (`Contact::touching`); null when this step reports no contact begin/end events.
FreeVelocities touch_velocities(const WorldEvents& events);
/// End of a step (after bodies are finished): contact begin/end/hit and sensor events.
void collect_step_events(WorldState& world);
/// `remove_body(id)`: the body's touches and overlaps end (reported after the next step).
void end_events_of_removed_body(WorldState& world, BodyId id);

}  // namespace impulse2d

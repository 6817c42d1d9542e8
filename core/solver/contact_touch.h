#pragma once
/// @file contact_touch.h
/// Whether a contact touches in a step, as contact events count it (events.h): judged on the
/// velocity each body would end the step with if nothing touched it. The prepare stage records
/// it on each awake contact while the contact is in the cache; the events stage judges the
/// set-aside (sleeping) contacts with the same test.

#include "core/contact.h"
#include "core/math.h"

namespace impulse2d {

/// Each body's free velocity over the step, by slot: what it carries into the step plus the
/// step's gravity and applied forces (world_events.h fills them). Null when no contact events
/// are wanted: then nothing records `Contact::touching`.
struct FreeVelocities {
  const vec2* linear = nullptr;    ///< m/s, per slot
  const float* angular = nullptr;  ///< rad/s, per slot
};

/// Relative approach speed (m/s, > 0 closing) of `point` of `contact` under the free velocities.
inline float free_approach_speed(const FreeVelocities& velocities, const Contact& contact,
                                 const ContactPoint& point) {
  const std::uint32_t a = contact.body_a.index;
  const std::uint32_t b = contact.body_b.index;
  const vec2 relative = (velocities.linear[b] + cross(velocities.angular[b], point.anchor_b)) -
                        (velocities.linear[a] + cross(velocities.angular[a], point.anchor_a));
  return -glm::dot(relative, contact.normal);
}

/// True when `contact` touches in a step of `dt` seconds: one of its points, moving freely
/// through the step from the gap it had when the step began, would end it less than `slop`
/// metres apart (or overlapping): a resting point, an overlap, or a speculative point the
/// bodies close within the step (the solver then stops them at the surface). A contact turned
/// off by the filter does not touch. Reads the points' depths and anchors (set by prepare).
/// (It reads only what the step began with, so it is the same in every solver, whose stored
/// impulses differ: a bounce's is dropped, the per-iteration solver keeps none. Inline: prepare
/// calls it on every contact.)
inline bool touches_in_step(const FreeVelocities& velocities, const Contact& contact, float slop,
                            float dt) {
  if (!contact.enabled) return false;
  for (int i = 0; i < contact.point_count; ++i) {
    const ContactPoint& point = contact.points[i];
    const float gap = -point.depth;
    if (gap - free_approach_speed(velocities, contact, point) * dt <= slop) return true;
  }
  return false;
}

}  // namespace impulse2d

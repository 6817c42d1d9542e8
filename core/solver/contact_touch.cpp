#include "core/solver/contact_touch.h"

namespace impulse2d {

float free_approach_speed(const FreeVelocities& velocities, const Contact& contact,
                          const ContactPoint& point) {
  const std::uint32_t a = contact.body_a.index;
  const std::uint32_t b = contact.body_b.index;
  const vec2 relative = (velocities.linear[b] + cross(velocities.angular[b], point.anchor_b)) -
                        (velocities.linear[a] + cross(velocities.angular[a], point.anchor_a));
  return -glm::dot(relative, contact.normal);
}

// This reads only what the step began with, so it is the same in every solver (whose stored
// impulses differ: a bounce's is dropped, the per-iteration solver keeps none).
bool touches_in_step(const FreeVelocities& velocities, const Contact& contact, float slop, float dt) {
  if (!contact.enabled) return false;
  for (int i = 0; i < contact.point_count; ++i) {
    const ContactPoint& point = contact.points[i];
    const float gap = -point.depth;
    if (gap - free_approach_speed(velocities, contact, point) * dt <= slop) return true;
  }
  return false;
}

}  // namespace impulse2d

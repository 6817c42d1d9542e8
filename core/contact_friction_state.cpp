#include "core/contact_friction_state.h"

#include "core/contact_solver_internal.h"

#include <cmath>

namespace impulse2d {

using namespace contact_detail;

void update_friction_state(Contact& contact, Body& a, Body& b) {
  const vec2 tangent = tangent_of(contact.normal);
  if (contact.sliding) {
    float fastest = 0.0f;
    for (int i = 0; i < contact.point_count; ++i) {
      const float slip = glm::dot(relative_velocity(a, b, contact.points[i]), tangent);
      fastest = std::max(fastest, std::fabs(slip));
    }
    if (fastest <= sticking_speed) contact.sliding = false;
    return;
  }
  bool at_static_limit = true;
  float total_normal_impulse = 0.0f;
  for (int i = 0; i < contact.point_count; ++i) {
    at_static_limit = at_static_limit && contact.points[i].friction_at_limit;
    total_normal_impulse += contact.points[i].normal_impulse;
  }
  if (!at_static_limit || !(total_normal_impulse > 0.0f)) {
    contact.steps_at_static_limit = 0;
    return;
  }
  // Only now the bodies' velocities (most contacts stop above, without reading them).
  float slip_sum = 0.0f;
  for (int i = 0; i < contact.point_count; ++i) {
    slip_sum += glm::dot(relative_velocity(a, b, contact.points[i]), tangent);
  }
  // Saturated friction that still reduced (or kept) the slip the contact brought into the
  // step holds against what drives it: it is only clearing residual slip of an unconverged
  // solve. Only a slip that grows under the full static limit means the cone is reached.
  const float end_slip = slip_sum / static_cast<float>(contact.point_count);
  if (!(std::fabs(end_slip) > std::fabs(contact.start_slip))) {
    contact.steps_at_static_limit = 0;
    return;
  }
  // The first step of a new contact starts cold (no warm start): its slip can grow under a
  // saturated limit before the normal impulses have converged. Two steps in a row cannot.
  if (++contact.steps_at_static_limit < 2) return;
  contact.steps_at_static_limit = 0;
  contact.sliding = true;
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const float dynamic_limit = contact.dynamic_friction * point.normal_impulse;
    const float accumulated = point.tangent_impulse < 0.0f ? -dynamic_limit : dynamic_limit;
    apply_impulse(a, b, contact.mass, point, tangent * (accumulated - point.tangent_impulse));
    point.tangent_impulse = accumulated;
  }
}

void update_friction_state(std::vector<Contact>& contacts, std::vector<Body>& bodies) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    update_friction_state(contact, bodies[contact.body_a.index], bodies[contact.body_b.index]);
  }
}

}  // namespace impulse2d

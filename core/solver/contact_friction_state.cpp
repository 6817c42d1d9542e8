#include "core/solver/contact_friction_state.h"

#include "core/solver/contact_solver_internal.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

using namespace contact_detail;


void break_loose(Contact& contact) {
  contact.sliding = true;
  contact.steps_at_static_limit = 0;
  contact.limit_slip = -1.0f;
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const float limit = contact.dynamic_friction * point.normal_impulse;
    point.tangent_impulse = std::clamp(point.tangent_impulse, -limit, limit);
  }
}

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
  const float last_limit_slip = contact.limit_slip;
  contact.limit_slip = -1.0f;
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
  // solve. Only a slip that grows under the full static limit means the cone is reached:
  // within the step (a force drives it), or from the end of last step, also at the limit, to
  // the end of this one (an impulse applied between the steps drives it: it raises the slip
  // the step starts with, so the step alone always sees it shrink).
  const float end_slip = std::fabs(slip_sum / static_cast<float>(contact.point_count));
  contact.limit_slip = end_slip;
  // While the load still changes (a cold start, a landing), the limit mu_s * Pn the solve
  // clamped at was off by up to mu_s * |dPn|, which lets the slip grow by that over the
  // tangent mass without the cone being reached: only growth beyond it counts.
  float tangent_mass = 0.0f;
  for (int i = 0; i < contact.point_count; ++i) tangent_mass += contact.points[i].tangent_mass;
  const float load_change = std::fabs(total_normal_impulse - contact.start_load);
  const float explained = tangent_mass > 0.0f
                              ? contact.static_friction * load_change / tangent_mass
                              : 0.0f;
  const bool grew_in_step = end_slip > std::fabs(contact.start_slip) + explained;
  const bool grew_since_last_step =
      last_limit_slip >= 0.0f && end_slip > last_limit_slip + explained;
  if (!grew_in_step && !grew_since_last_step) {
    contact.steps_at_static_limit = 0;
    return;
  }
  // Two steps in a row: one can still be a cold start's (the first step of a new contact is
  // solved without a warm start, and its load is not yet the solve's to judge).
  if (++contact.steps_at_static_limit < 2) return;
  contact.steps_at_static_limit = 0;
  contact.limit_slip = -1.0f;
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

#include "core/soft_contact_solver.h"

#include "core/contact_bounce.h"
#include "core/contact_solver_internal.h"

#include <algorithm>

namespace impulse2d {

using namespace contact_detail;

void solve_contacts_soft(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const SolverContext& context, bool use_bias) {
  const float inverse_h = 1.0f / context.substep;
  for (Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const bool against_fixed = contact.mass.inverse_mass_a == 0.0f || contact.mass.inverse_mass_b == 0.0f;
    const Softness& softness = against_fixed ? context.static_softness : context.dynamic_softness;
    const vec2 normal = contact.normal;

    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      float target_speed = 0.0f;  // smallest relative normal velocity allowed, m/s
      float mass_scale = 1.0f;
      float impulse_scale = 0.0f;
      if (point.bouncing) {
        target_speed = point.velocity_bias;
      } else {
        const float separation = current_separation(a, b, contact, point);
        if (separation > 0.0f) {
          // Relaxing only takes the push-out speed off touching points; a point still apart
          // keeps its impulse (clamping its approach here would slow a falling body before
          // the next sub-step's solve sees it).
          if (!use_bias) continue;
          target_speed = -separation * inverse_h;  // may approach until the gap closes
        } else if (use_bias) {
          target_speed = std::min(-softness.bias_rate * separation, context.push_max_speed);
          mass_scale = softness.mass_scale;
          impulse_scale = softness.impulse_scale;
        }
      }
      const float normal_speed = glm::dot(relative_velocity(a, b, point), normal);
      const float unclamped = point.normal_impulse -
                              point.normal_mass * mass_scale * (normal_speed - target_speed) -
                              impulse_scale * point.normal_impulse;
      const float accumulated = std::max(unclamped, 0.0f);
      const float change = accumulated - point.normal_impulse;
      point.normal_impulse = accumulated;
      apply_impulse(a, b, contact.mass, point, normal * change);
    }

    // Friction in the relax pass only (as Box2D v3 does): against the normal impulses without
    // the soft push-out, so the push-out never raises the Coulomb limit.
    if (context.friction && !use_bias) solve_friction_points(a, b, contact);
  }
}

}  // namespace impulse2d

#include "core/soft_contact_solver.h"

#include "core/contact_bounce.h"
#include "core/contact_solver_internal.h"

#include <algorithm>

namespace impulse2d {

using namespace contact_detail;

namespace {

// Static friction of a sticking contact in the biased pass: each point's tangential speed is
// driven to the speed that takes back its drift from where it stuck at `bias_rate` (1/s, the
// contact's own stiffness), no faster than `max_speed` (m/s), within the Coulomb limit
// mu_s * Pn. The relax pass then solves plain friction, so no pull-back speed is left in the
// velocities (and the stick/slip state reads the true slip), as the normal push-out is
// relaxed. Without it a loaded point slips a little every sub-step (the Gauss-Seidel residual)
// and the slips add up: the 100-row pyramid spread 12 cm sideways in 500 steps, 0.5 cm with
// it. Tried and rejected: the pull-back in the relax pass (the stick/slip state read the
// pull-back as slip and broke resting contacts loose), and a soft (spring-damper) friction
// (a weaker friction: the pyramid sank 10 cm more).
void solve_anchored_friction(Body& a, Body& b, Contact& contact, float bias_rate,
                             float max_speed) {
  const vec2 tangent = tangent_of(contact.normal);
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    const float target_speed =
        std::clamp(-bias_rate * friction_drift(a, b, contact, point), -max_speed, max_speed);
    const float tangent_speed = glm::dot(relative_velocity(a, b, point), tangent);
    const float unclamped =
        point.tangent_impulse - point.tangent_mass * (tangent_speed - target_speed);
    const float limit = contact.static_friction * point.normal_impulse;
    const float accumulated = std::clamp(unclamped, -limit, limit);
    const float change = accumulated - point.tangent_impulse;
    point.tangent_impulse = accumulated;
    apply_impulse(a, b, contact.mass, point, tangent * change);
  }
}

}  // namespace

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
      if (point.waiting) {
        continue;  // an elastic point that neither approaches nor touches sits this step out
      } else if (point.bouncing) {
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

    // Box2D v3 solves friction in the relax pass only, against the normal impulses without the
    // soft push-out, so the push-out never raises the Coulomb limit; a sticking contact here
    // also takes back its drift in the biased pass.
    if (!context.friction) continue;
    if (!use_bias) {
      solve_friction_points(a, b, contact);
    } else if (!contact.sliding) {
      solve_anchored_friction(a, b, contact, softness.bias_rate, context.push_max_speed);
    }
  }
}

}  // namespace impulse2d

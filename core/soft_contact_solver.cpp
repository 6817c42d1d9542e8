#include "core/soft_contact_solver.h"

#include "core/contact_solver_internal.h"

#include <algorithm>

namespace impulse2d {

using namespace contact_detail;

Softness make_soft(float hertz, float damping_ratio, float h) {
  constexpr float two_pi = 6.28318530717958647692f;
  const float omega = two_pi * hertz;
  const float stiffness_term = 2.0f * damping_ratio + h * omega;
  const float implicit_term = h * omega * stiffness_term;
  const float inverse_denominator = 1.0f / (1.0f + implicit_term);
  Softness softness;
  softness.bias_rate = omega / stiffness_term;
  softness.mass_scale = implicit_term * inverse_denominator;
  softness.impulse_scale = inverse_denominator;
  return softness;
}

void solve_contacts_soft(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                         const WorldSettings& settings, float h, bool use_bias) {
  // A spring stiffer than a quarter of the sub-step rate would be under-resolved in time.
  const float hertz = std::min(settings.contact_hertz, 0.25f / h);
  const Softness dynamic_softness = make_soft(hertz, settings.contact_damping_ratio, h);
  // Against an immovable body only one side gives: twice as stiff keeps the same feel.
  const Softness static_softness = make_soft(2.0f * hertz, settings.contact_damping_ratio, h);
  const float inverse_h = 1.0f / h;
  for (Contact& contact : contacts) {
    if (!is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    const Softness& softness =
        (a.inverse_mass == 0.0f || b.inverse_mass == 0.0f) ? static_softness : dynamic_softness;
    const vec2 normal = contact.normal;

    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      const vec2 surface_a = a.transform.apply(point.local_anchor_a);
      const vec2 surface_b = b.transform.apply(point.local_anchor_b);
      const float separation = glm::dot(surface_b - surface_a, normal);
      float bias = 0.0f;
      float mass_scale = 1.0f;
      float impulse_scale = 0.0f;
      if (separation > 0.0f) {
        bias = separation * inverse_h;  // may approach until the gap closes
      } else if (use_bias) {
        bias = std::max(softness.bias_rate * separation, -settings.contact_push_max_speed);
        mass_scale = softness.mass_scale;
        impulse_scale = softness.impulse_scale;
      }
      const float normal_speed = glm::dot(relative_velocity(a, b, point), normal);
      const float unclamped = point.normal_impulse - point.normal_mass * mass_scale * (normal_speed + bias) -
                              impulse_scale * point.normal_impulse;
      const float accumulated = std::max(unclamped, 0.0f);
      const float change = accumulated - point.normal_impulse;
      point.normal_impulse = accumulated;
      point.max_normal_impulse = std::max(point.max_normal_impulse, change);
      apply_impulse(a, b, mass, point, normal * change);
    }

    if (settings.enable_friction) solve_friction_points(a, b, mass, contact);
  }
}

void apply_restitution(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                       const WorldSettings& settings) {
  for (Contact& contact : contacts) {
    if (contact.restitution == 0.0f || !is_solvable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const PairMass mass = pair_mass(a, b, settings);
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      // velocity_bias is -e times the prepare-time approach speed, or 0 below the threshold.
      if (point.velocity_bias == 0.0f || point.max_normal_impulse == 0.0f) continue;
      const float normal_speed = glm::dot(relative_velocity(a, b, point), contact.normal);
      const float accumulated =
          std::max(point.normal_impulse - point.normal_mass * (normal_speed - point.velocity_bias), 0.0f);
      const float change = accumulated - point.normal_impulse;
      point.normal_impulse = accumulated;
      apply_impulse(a, b, mass, point, contact.normal * change);
    }
  }
}

}  // namespace impulse2d

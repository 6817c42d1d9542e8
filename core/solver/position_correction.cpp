#include "core/solver/position_correction.h"

#include "core/solver/integrate.h"

#include <algorithm>

namespace impulse2d {

namespace {
bool is_correctable(const Contact& contact, const std::vector<Body>& bodies) {
  return contact.enabled && (bodies[contact.body_a.index].inverse_mass > 0.0f ||
                             bodies[contact.body_b.index].inverse_mass > 0.0f);
}
}  // namespace

void correct_positions_linear(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                              const WorldSettings& settings) {
  for (const Contact& contact : contacts) {
    if (!is_correctable(contact, bodies)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    float depth = 0.0f;
    for (int i = 0; i < contact.point_count; ++i) {
      if (!contact.points[i].waiting) depth = std::max(depth, contact.points[i].depth);
    }
    const float inverse_mass_sum = a.inverse_mass + b.inverse_mass;
    const vec2 correction = contact.normal * (std::max(depth - settings.slop, 0.0f) /
                                              inverse_mass_sum * settings.correction_percent);
    a.transform.position -= correction * a.inverse_mass;
    b.transform.position += correction * b.inverse_mass;
  }
}

float correct_positions_nonlinear(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                  const WorldSettings& settings) {
  float deepest = 0.0f;
  for (int iteration = 0; iteration < settings.position_iterations; ++iteration) {
    deepest = 0.0f;
    for (const Contact& contact : contacts) {
      if (!is_correctable(contact, bodies)) continue;
      Body& a = bodies[contact.body_a.index];
      Body& b = bodies[contact.body_b.index];
      const float inverse_inertia_a = effective_inverse_inertia(a, settings);
      const float inverse_inertia_b = effective_inverse_inertia(b, settings);
      const vec2 normal = contact.normal;
      for (int i = 0; i < contact.point_count; ++i) {
        const ContactPoint& point = contact.points[i];
        if (point.waiting) continue;  // sat out this step's solve: its overlap is next step's
        const vec2 core_a = a.transform.apply(point.local_anchor_a);
        const vec2 core_b = b.transform.apply(point.local_anchor_b);
        const float separation = glm::dot(core_b - core_a, normal) - point.rounding;
        // The surface points: each core point moved out by its body's rounding.
        const vec2 surface_a = core_a + normal * rounding_of(a, contact.child_a);
        const vec2 surface_b = core_b - normal * rounding_of(b, contact.child_b);
        deepest = std::max(deepest, -separation);
        const float error = std::clamp(settings.correction_percent * (separation + settings.slop),
                                       -settings.max_correction, 0.0f);
        if (error == 0.0f) continue;
        const vec2 midpoint = 0.5f * (surface_a + surface_b);
        const vec2 arm_a = midpoint - a.transform.position;
        const vec2 arm_b = midpoint - b.transform.position;
        const float turn_a = cross(arm_a, normal);
        const float turn_b = cross(arm_b, normal);
        const float k = a.inverse_mass + b.inverse_mass + inverse_inertia_a * turn_a * turn_a +
                        inverse_inertia_b * turn_b * turn_b;
        if (k <= 0.0f) continue;
        const vec2 impulse = normal * (-error / k);
        a.transform.position -= impulse * a.inverse_mass;
        b.transform.position += impulse * b.inverse_mass;
        if (inverse_inertia_a != 0.0f) {
          a.angle -= inverse_inertia_a * cross(arm_a, impulse);
          a.transform.rotation = Rotation::from_angle(a.angle);
        }
        if (inverse_inertia_b != 0.0f) {
          b.angle += inverse_inertia_b * cross(arm_b, impulse);
          b.transform.rotation = Rotation::from_angle(b.angle);
        }
      }
    }
  }
  return deepest;
}

}  // namespace impulse2d

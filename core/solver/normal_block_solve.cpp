#include "core/solver/normal_block_solve.h"

#include "core/solver/contact_solver_internal.h"

namespace impulse2d {

using namespace contact_detail;

bool solve_normal_block(Body& a, Body& b, Contact& contact, const PairMass& mass) {
  ContactPoint& p1 = contact.points[0];
  ContactPoint& p2 = contact.points[1];
  const vec2 normal = contact.normal;
  const float arm_a1 = cross(p1.anchor_a, normal), arm_b1 = cross(p1.anchor_b, normal);
  const float arm_a2 = cross(p2.anchor_a, normal), arm_b2 = cross(p2.anchor_b, normal);
  const float linear = mass.inverse_mass_a + mass.inverse_mass_b;
  const float k11 = linear + mass.inverse_inertia_a * arm_a1 * arm_a1 + mass.inverse_inertia_b * arm_b1 * arm_b1;
  const float k22 = linear + mass.inverse_inertia_a * arm_a2 * arm_a2 + mass.inverse_inertia_b * arm_b2 * arm_b2;
  const float k12 = linear + mass.inverse_inertia_a * arm_a1 * arm_a2 + mass.inverse_inertia_b * arm_b1 * arm_b2;
  const float determinant = k11 * k22 - k12 * k12;
  constexpr float max_condition = 1000.0f;
  if (!(k11 * k11 < max_condition * determinant)) return false;

  const vec2 old_impulse{p1.normal_impulse, p2.normal_impulse};
  const float speed1 = glm::dot(relative_velocity(a, b, p1), normal) - p1.velocity_bias;
  const float speed2 = glm::dot(relative_velocity(a, b, p2), normal) - p2.velocity_bias;
  const vec2 rhs{speed1 - (k11 * old_impulse.x + k12 * old_impulse.y),
                 speed2 - (k12 * old_impulse.x + k22 * old_impulse.y)};
  vec2 impulse;
  // Case 1: both points push. x = -K^-1 b.
  impulse = vec2(-(k22 * rhs.x - k12 * rhs.y), -(-k12 * rhs.x + k11 * rhs.y)) / determinant;
  if (!(impulse.x >= 0.0f && impulse.y >= 0.0f)) {
    // Case 2: only the first pushes; the second must then be separating.
    impulse = vec2(-rhs.x / k11, 0.0f);
    if (!(impulse.x >= 0.0f && k12 * impulse.x + rhs.y >= 0.0f)) {
      // Case 3: only the second pushes.
      impulse = vec2(0.0f, -rhs.y / k22);
      if (!(impulse.y >= 0.0f && k12 * impulse.y + rhs.x >= 0.0f)) {
        // Case 4: neither pushes; both must be separating already.
        impulse = vec2(0.0f);
        if (!(rhs.x >= 0.0f && rhs.y >= 0.0f)) return false;
      }
    }
  }
  apply_impulse(a, b, mass, p1, normal * (impulse.x - old_impulse.x));
  apply_impulse(a, b, mass, p2, normal * (impulse.y - old_impulse.y));
  p1.normal_impulse = impulse.x;
  p2.normal_impulse = impulse.y;
  return true;
}

}  // namespace impulse2d

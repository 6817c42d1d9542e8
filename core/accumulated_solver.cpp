#include "core/accumulated_solver.h"

#include "core/contact_bounce.h"
#include "core/contact_friction_state.h"
#include "core/contact_prepare.h"
#include "core/contact_solver_internal.h"

namespace impulse2d {

using namespace contact_detail;

namespace {

// Solves both normal impulses of a 2-point manifold at once: find x >= 0 with
// v = K x + b >= 0 and x . v = 0 (a 2x2 linear complementarity problem) by trying the four
// cases in turn, where K is the 2x2 effective-mass matrix and b the velocities (less their
// targets) without the accumulated impulses. Returns false (solve point by point instead)
// when K is ill-conditioned or no case holds.
bool solve_normal_block(Body& a, Body& b, Contact& contact) {
  const PairMass& mass = contact.mass;
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

// One pass over every contact: the normal impulses, then friction against the limit they
// set (Box2D v3's order: the Coulomb limit is never a pass out of date).
void solve_pass(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                const SolverContext& context) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    if (!(context.block_solver && contact.point_count == 2 && solve_normal_block(a, b, contact))) {
      for (int i = 0; i < contact.point_count; ++i) {
        ContactPoint& point = contact.points[i];
        push_normal_to(a, b, contact, point, point.velocity_bias);
      }
    }
    if (context.friction) solve_friction_points(a, b, contact);
  }
}

}  // namespace

void AccumulatedSolver::step(SolverStages& stages, const SolverContext& context) const {
  const float h = context.substep;
  for (int substep = 0; substep < context.substeps; ++substep) {
    stages.find_contacts(h);
    std::vector<Contact>& contacts = stages.solver_contacts();
    std::vector<Body>& bodies = stages.solver_bodies();
    prepare_contacts(contacts, bodies, context);
    if (context.explicit_euler) stages.integrate_positions(h);  // with the old velocity
    stages.integrate_velocities(h);
    plan_contact_speeds(contacts, bodies, context, h, /*bounces_only=*/false,
                        stages.solver_body_flags());
    if (context.warm_starting) warm_start_contacts(contacts, bodies);
    for (int i = 0; i < context.velocity_iterations; ++i) solve_pass(contacts, bodies, context);
    if (context.friction) update_friction_state(contacts, bodies);
    if (!context.explicit_euler) stages.integrate_positions(h);  // with the new velocity
    apply_bounces(contacts, bodies);
    stages.correct_positions();
  }
}

}  // namespace impulse2d

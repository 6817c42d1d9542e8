#include "core/solver/per_iteration_solver.h"

#include "core/solver/contact_bounce.h"
#include "core/solver/contact_prepare.h"
#include "core/solver/joint_solver.h"
#include "core/solver/contact_solver_internal.h"

#include <cmath>

namespace impulse2d {

using namespace contact_detail;

namespace {

void solve_pass(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                const SolverContext& context) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const vec2 normal = contact.normal;
    for (int i = 0; i < contact.point_count; ++i) {
      ContactPoint& point = contact.points[i];
      const float normal_speed = glm::dot(relative_velocity(a, b, point), normal);
      // Already at or above its target (separating, or closing less than its gap): this point
      // needs nothing (the others may).
      if (normal_speed >= point.velocity_bias) continue;
      const float normal_impulse = -(normal_speed - point.velocity_bias) * point.normal_mass;
      apply_impulse(a, b, contact.mass, point, normal * normal_impulse);
      point.normal_impulse = normal_impulse;

      if (!context.friction) continue;
      const vec2 velocity = relative_velocity(a, b, point);
      const vec2 tangential = velocity - normal * glm::dot(velocity, normal);
      const float tangential_speed = glm::length(tangential);
      if (tangential_speed <= 0.0f) continue;
      const vec2 tangent = tangential / tangential_speed;
      const float k_tangent = inverse_effective_mass(contact.mass, point, tangent);
      if (k_tangent <= 0.0f) continue;
      const float sticking_impulse = -tangential_speed / k_tangent;
      float friction_impulse = sticking_impulse;
      contact.sliding = std::fabs(sticking_impulse) >= normal_impulse * contact.static_friction;
      if (contact.sliding) friction_impulse = -normal_impulse * contact.dynamic_friction;
      apply_impulse(a, b, contact.mass, point, tangent * friction_impulse);
      // Stored in the fixed tangent frame so drawing and statistics read one convention.
      point.tangent_impulse = friction_impulse * glm::dot(tangent, tangent_of(normal));
    }
  }
}

}  // namespace

void PerIterationSolver::step(SolverStages& stages, const SolverContext& context) const {
  const float h = context.substep;
  for (int substep = 0; substep < context.substeps; ++substep) {
    stages.find_contacts(h, nullptr);
    std::vector<Contact>& contacts = stages.solver_contacts();
    std::vector<Body>& bodies = stages.solver_bodies();
    prepare_contacts(contacts, bodies, context);
    if (context.explicit_euler) stages.integrate_positions(h);  // with the old velocity
    stages.integrate_velocities(h);
    for (Contact& contact : contacts) {
      for (int i = 0; i < contact.point_count; ++i) {
        contact.points[i].normal_impulse = 0.0f;  // no memory between steps
        contact.points[i].tangent_impulse = 0.0f;
      }
    }
    plan_contact_speeds(contacts, bodies, context, h, /*bounces_only=*/false,
                        stages.solver_body_flags(), stages.solver_bouncing_contacts());
    // Joints in the tutorial's form: no memory between steps (nothing warm started), each
    // pass's limit impulse only pushes; motors and force limits bound the step's running total.
    const bool joints = stages.has_joints();
    JointPass joint_pass;
    joint_pass.h = h;
    joint_pass.joint_softness = context.joint_softness;
    joint_pass.accumulate = false;
    if (joints) stages.prepare_joints(h, /*clear_impulses=*/true);
    for (int i = 0; i < context.velocity_iterations; ++i) {
      if (joints) solve_joints(stages.solver_joints(), bodies, joint_pass);
      solve_pass(contacts, bodies, context);
    }
    if (!context.explicit_euler) stages.integrate_positions(h);  // with the new velocity
    if (joints) {
      // Relax (the soft step's): take the joints' bias velocity back out after it moved them.
      joint_pass.use_bias = false;
      for (int i = 0; i < context.velocity_iterations; ++i) solve_joints(stages.solver_joints(), bodies, joint_pass);
    }
    apply_bounces(contacts, bodies, stages.solver_bouncing_contacts());
    stages.correct_positions();
  }
}

}  // namespace impulse2d

#include "core/solver/accumulated_solver.h"

#include "core/solver/contact_bounce.h"
#include "core/solver/contact_friction_state.h"
#include "core/solver/contact_prepare.h"
#include "core/solver/contact_solver_internal.h"
#include "core/solver/joint_solver.h"
#include "core/solver/normal_block_solve.h"
#include "core/solver/shock_propagation.h"

namespace impulse2d {

using namespace contact_detail;

namespace {

// One pass over every contact: the normal impulses, then friction against the limit they
// set (Box2D v3's order: the Coulomb limit is never a pass out of date).
void solve_pass(std::vector<Contact>& contacts, std::vector<Body>& bodies,
                const SolverContext& context) {
  for (Contact& contact : contacts) {
    if (!is_solvable(contact)) continue;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    if (!(context.block_solver && contact.point_count == 2 && solve_normal_block(a, b, contact, contact.mass))) {
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
    stages.find_contacts(h, nullptr);
    std::vector<Contact>& contacts = stages.solver_contacts();
    std::vector<Body>& bodies = stages.solver_bodies();
    prepare_contacts(contacts, bodies, context);
    if (context.explicit_euler) stages.integrate_positions(h);  // with the old velocity
    stages.integrate_velocities(h);
    plan_contact_speeds(contacts, bodies, context, h, /*bounces_only=*/false,
                        stages.solver_body_flags(), stages.solver_bouncing_contacts());
    // Joints: warm-started accumulated impulses, solved before the contacts in every pass with
    // the soft position bias, and relaxed without it after the positions move.
    const bool joints = stages.has_joints();
    JointPass joint_pass;  // (declared here: the relax below reuses it)
    joint_pass.h = h;
    joint_pass.joint_softness = context.joint_softness;
    if (joints) {
      stages.prepare_joints(h, /*clear_impulses=*/!context.warm_starting);
      if (context.warm_starting) warm_start_joints(stages.solver_joints(), bodies);
    }
    if (context.warm_starting) warm_start_contacts(contacts, bodies);
    for (int i = 0; i < context.velocity_iterations; ++i) {
      if (joints) solve_joints(stages.solver_joints(), bodies, joint_pass);
      solve_pass(contacts, bodies, context);
    }
    if (context.shock_propagation) {
      SupportOrder& order = stages.solver_support_order();
      // Each sub-step collides afresh: its contacts are new.
      build_support_order(contacts, bodies, context.gravity, context.velocity_iterations,
                          /*same_contacts=*/false, order);
      solve_shock_pass(contacts, bodies, order, context.block_solver, context.friction);
    }
    if (context.friction) update_friction_state(contacts, bodies);
    if (!context.explicit_euler) stages.integrate_positions(h);  // with the new velocity
    if (joints) {
      // Relax (the soft step's): the joints' bias velocity has moved the bodies back towards
      // their anchors; without it the next step would start with that velocity still in them.
      joint_pass.use_bias = false;
      for (int i = 0; i < context.velocity_iterations; ++i) solve_joints(stages.solver_joints(), bodies, joint_pass);
    }
    apply_bounces(contacts, bodies, stages.solver_bouncing_contacts());
    stages.correct_positions();
  }
}

}  // namespace impulse2d

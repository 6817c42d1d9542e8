#include "core/solver/soft_step_solver.h"

#include "core/solver/contact_bounce.h"
#include "core/solver/contact_friction_state.h"
#include "core/solver/contact_solver_internal.h"
#include "core/solver/joint_solver.h"
#include "core/solver/shock_propagation.h"
#include "core/solver/wide_contact_solver.h"

namespace impulse2d {

using namespace contact_detail;

namespace {

// Joint passes per velocity iteration (soft and relax). The joints' rigid parts are stiff (half
// the sub-step rate, solver_context.cpp), and one Gauss-Seidel pass a sub-step leaves a chain's
// joints fighting each other: at 120 Hz one pass lets a 20-link chain fly apart, four hold it
// to 0.66 mm (1:100 load: 4.1 mm; eight passes change neither). Joints are few beside
// contacts, so the passes cost little.
constexpr int kJointPasses = 4;

// The bounce plans' contacts written out of (and later read back into) the wide solver's lanes.
class LaneWriteOut final : public ContactWriteOut {
 public:
  LaneWriteOut(WideContactSolver& wide, std::vector<Contact>& contacts)
      : wide_(wide), contacts_(contacts) {}
  void write_out(std::uint32_t index) override { wide_.write_out(contacts_, index); }

 private:
  WideContactSolver& wide_;
  std::vector<Contact>& contacts_;
};

}  // namespace

void SoftStepSolver::step(SolverStages& stages, const SolverContext& context) const {
  std::vector<Body>& bodies = stages.solver_bodies();
  WideContactSolver& wide = stages.solver_wide_contacts();
  // Once: the sub-steps track each point's separation through its anchors. Each contact is
  // prepared and coloured as the narrow phase finishes it, while it is in the cache.
  const bool joints = stages.has_joints();
  wide.begin_step(bodies, context, context.solver_lanes, stages.workers(), /*allow_batches=*/!joints);
  stages.find_contacts(context.time_step, &wide);
  std::vector<Contact>& contacts = stages.solver_contacts();
  wide.finish_step(contacts);
  const bool may_bounce = context.restitution && wide.has_elastic_contacts();
  // Heavy bodies on light ones: a ground-up pass with the lower body held fixed after each
  // sub-step's solve (as the accumulated solver does after its iterations), else one soft pass
  // a sub-step lets a 1:1000 load squeeze through the light body.
  const bool shock = wide.has_heavy_on_light();
  // The sub-steps work on the compact body states; the bodies are written once at the end
  // (and around the bounce stages, which work on them).
  stages.begin_solver_bodies();
  SolverBodies& states = stages.solver_body_states();
  if (wide.batched()) {
    solve_island_batches(stages, context, wide, states);
  } else {
    solve_pass_by_pass(stages, context, wide, may_bounce, shock);
  }
  finish_step(stages, context, wide);
}

void SoftStepSolver::solve_island_batches(SolverStages& stages, const SolverContext& context,
                                          WideContactSolver& wide, SolverBodies& states) const {
  // No joints, bounces or shock pass: the sub-steps of one batch of islands touch no body of
  // another, so each batch runs all of them while its blocks and bodies are in the cache
  // (each body sees the same operations in the same order as pass by pass: the same bits).
  // The batches are independent work for the workers, and the rest batch (bodies without
  // contacts) only integrates.
  const float h = context.substep;
  const IslandBatches& islands = wide.islands();
  const std::size_t contact_batches = islands.batch_count();
  SolverBody* solver_states = states.states();
  parallel_for(stages.workers(), contact_batches + 1, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t batch = begin; batch < end; ++batch) {
      const std::uint32_t* slots = islands.bodies_of(batch);
      const std::size_t slot_count = islands.body_count(batch);
      const bool has_contacts = batch < contact_batches;
      for (int substep = 0; substep < context.substeps; ++substep) {
        states.integrate_velocities(h, slots, slot_count);
        if (has_contacts) {
          if (context.warm_starting) wide.warm_start_batch(batch, solver_states);
          for (int i = 0; i < context.velocity_iterations; ++i) {
            wide.solve_batch(batch, context, /*use_bias=*/true, solver_states);
          }
        }
        states.integrate_positions(h, slots, slot_count);
        for (int i = 0; has_contacts && i < context.velocity_iterations; ++i) {
          wide.solve_batch(batch, context, /*use_bias=*/false, solver_states);  // relax
        }
      }
    }
  });
}

void SoftStepSolver::solve_pass_by_pass(SolverStages& stages, const SolverContext& context,
                                        WideContactSolver& wide, bool may_bounce,
                                        bool shock) const {
  const float h = context.substep;
  std::vector<Body>& bodies = stages.solver_bodies();
  std::vector<Contact>& contacts = stages.solver_contacts();
  SolverBodies& states = stages.solver_body_states();
  // Joints (Box2D v3's order): in every stage before the contacts, same sub-steps and relax.
  const bool joints = stages.has_joints();
  std::vector<Joint>& joint_list = stages.solver_joints();
  JointPass joint_pass;
  joint_pass.h = h;
  joint_pass.joint_softness = context.joint_softness;
  if (joints) stages.prepare_joints(h, /*clear_impulses=*/!context.warm_starting);
  // The plans ask for each contact they read or change (ContactWriteOut): only those go out
  // and back in (for the rest, reading back what was written out would be a copy).
  const bool full = stages.full_bounce_stages();  // a test's twin: skip nothing
  LaneWriteOut lanes(wide, contacts);
  for (int substep = 0; substep < context.substeps; ++substep) {
    stages.integrate_solver_velocities(h);
    bool bounces = false;  // some point bounces in this sub-step
    if (may_bounce) {
      states.store(bodies);
      if (full) {
        wide.store_impulses(contacts);
        bounces = plan_bounces(contacts, bodies, context, h, /*bounces_only=*/true,
                               stages.solver_body_flags(), stages.solver_bouncing_contacts());
        plan_waits(contacts, bodies, context, h, /*bounces_only=*/true, stages.solver_body_flags());
        wide.load_points(contacts);
      } else {
        bounces = plan_bounces(contacts, bodies, context, h, /*bounces_only=*/true,
                               stages.solver_body_flags(), stages.solver_bouncing_contacts(), &lanes);
        // Without a bounce and with no earlier plan to undo, no point waits or stops waiting.
        if (bounces || wide.has_written_out()) {
          plan_waits(contacts, bodies, context, h, /*bounces_only=*/true,
                     stages.solver_body_flags(), &lanes);
        }
        wide.read_back_written(contacts);
      }
    }
    if (joints && context.warm_starting) warm_start_joints(joint_list, states.states());
    if (context.warm_starting) wide.warm_start(states.states(), stages.workers());
    joint_pass.use_bias = true;
    for (int i = 0; i < context.velocity_iterations; ++i) {
      for (int pass = 0; joints && pass < kJointPasses; ++pass) {
        solve_joints(joint_list, states.states(), joint_pass);
      }
      wide.solve(context, /*use_bias=*/true, states.states(), stages.workers());
    }
    if (shock) {
      wide.store_impulses(contacts);
      states.store(bodies);
      SupportOrder& order = stages.solver_support_order();
      // The step's contacts: after the first sub-step, an order that still holds is kept.
      build_support_order(contacts, bodies, context.gravity, context.velocity_iterations,
                          /*same_contacts=*/substep > 0 && !full, order);
      if (full || !order.contacts_upward.empty()) {  // else the pass moves nothing: no read-back
        solve_shock_pass(contacts, bodies, order, context.block_solver, context.friction);
        states.load(bodies);
      }
    }
    stages.integrate_solver_positions(h);
    joint_pass.use_bias = false;
    for (int i = 0; i < context.velocity_iterations; ++i) {
      for (int pass = 0; joints && pass < kJointPasses; ++pass) {
        solve_joints(joint_list, states.states(), joint_pass);
      }
      wide.solve(context, /*use_bias=*/false, states.states(), stages.workers());  // relax
    }
    // Without a bounce, applying them changes nothing, and writing the states and impulses out
    // and reading them back in gives the same bits: both are skipped. With one, only the
    // bouncing contacts and their bodies are read and changed: only they go out and back in
    // (what every later reader of the contacts and bodies reads is written out in full first).
    if (full && may_bounce) {
      wide.store_impulses(contacts);
      states.store(bodies);
      apply_bounces(contacts, bodies, stages.solver_bouncing_contacts());
      states.load(bodies);
      wide.load_points(contacts);
    } else if (bounces) {
      const std::vector<std::uint32_t>& bouncing = stages.solver_bouncing_contacts();
      for (const std::uint32_t index : bouncing) wide.write_out(contacts, index);
      states.store_bodies_of(bodies, contacts, bouncing);
      apply_bounces(contacts, bodies, bouncing);
      states.load_bodies_of(bodies, contacts, bouncing);
      wide.read_back_written(contacts);
    }
  }
}

void SoftStepSolver::finish_step(SolverStages& stages, const SolverContext& context,
                                 WideContactSolver& wide) const {
  std::vector<Body>& bodies = stages.solver_bodies();
  std::vector<Contact>& contacts = stages.solver_contacts();
  SolverBodies& states = stages.solver_body_states();
  states.store(bodies, stages.workers());
  if (states.has_bullets()) stages.sweep_bullets(context.time_step);
  // One walk in the list's order writes the impulses back and then, with friction, switches
  // each contact between sticking and sliding (the switch reads them).
  wide.store_impulses(contacts, [&](Contact& contact) {
    if (!context.friction || !is_solvable(contact)) return;
    Body& a = bodies[contact.body_a.index];
    Body& b = bodies[contact.body_b.index];
    const bool at_limit = contact.points[0].friction_at_limit;
    update_friction_state(contact, a, b);
    if (!contact.sliding && !at_limit) return;
    // A sliding contact sticks, when it does, where it came to rest, and a sticking one whose
    // friction was at its limit slipped for real: their points' drift so far is no longer
    // taken back (only residual slip under a friction that held is). (The switch changes
    // velocities only, the drift reads poses, so one walk does both.)
    for (int i = 0; i < contact.point_count; ++i) {
      contact.points[i].stick_offset += friction_drift(a, b, contact, contact.points[i]);
    }
  });
}

}  // namespace impulse2d

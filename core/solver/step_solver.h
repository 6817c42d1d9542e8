#pragma once
/// @file step_solver.h
/// One small interface per solver method: a method drives the stages of a step (collide,
/// integrate, solve contacts, correct positions) in its own order. Adding a method touches six
/// files: an enumerator in `SolverMethod` (core/settings.h); its name in `solver_name`, its
/// place in `solver_methods` and its budget in `settings_for` (core/settings.cpp); a
/// `StepSolver` in its own file pair in core/solver/, listed in core/CMakeLists.txt; and one
/// line in `make_step_solver` (core/solver/step_solver.cpp). Scene files, the lab's sweeps and
/// labels, the CLI and charts take the name and the list from there.

#include "core/contact.h"
#include "core/solver/body_state.h"
#include "core/solver/contact_visitor.h"
#include "core/solver/shock_propagation.h"
#include "core/solver/solver_bodies.h"
#include "core/solver/solver_context.h"
#include "core/solver/wide_contact_solver.h"
#include "core/solver/world_state.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace impulse2d {

/// The pipeline stages a solver method calls, over one world's state, each timed into its
/// `stats`. A plain object made for the step (no virtual calls): the solver method chooses
/// the order, the stages do the work (Box2D v3's stages over `b2World`, Jolt's jobs over
/// `PhysicsSystem`).
class SolverStages {
 public:
  /// The stages of `world`'s step.
  explicit SolverStages(WorldState& world)
      : world_(world),
        pool_(world.workers.get(world.settings.worker_count, world.settings.task_system)) {}

  /// Broad phase, then narrow phase through the jump table: rebuilds `contacts()` with
  /// speculative points for the coming `dt` seconds. `visitor` (may be null) sees each contact
  /// of the new list as the narrow phase finishes it (`contact_visitor.h`).
  void find_contacts(float dt, ContactVisitor* visitor);
  /// Adds gravity, forces and damping to every awake dynamic body's velocity over `dt` seconds.
  void integrate_velocities(float dt);
  /// Moves every awake body by its velocity over `dt` seconds (bullets swept if enabled).
  void integrate_positions(float dt);
  /// Loads `solver_body_states()` from the bodies for this step (after `find_contacts`).
  void begin_solver_bodies();
  /// `integrate_velocities` on `solver_body_states()` instead of the bodies.
  void integrate_solver_velocities(float dt);
  /// `integrate_positions` on `solver_body_states()` instead of the bodies (bullets are not
  /// swept: see `sweep_bullets`).
  void integrate_solver_positions(float dt);
  /// Moves every bullet back to where its motion over the last `dt` seconds first met another
  /// body (continuous collision, when enabled), on the bodies. The soft step sweeps once a
  /// step, after its sub-steps, as its contacts are found once a step: a bullet stopped
  /// within a sub-step would have no contact to meet in the next one.
  void sweep_bullets(float dt);
  /// True when the world has joints (the solvers' joint passes have work).
  bool has_joints() const { return world_.living_joint_count > 0; }
  /// Prepares the joints for a step of `h`-second sub-steps (`joint_solver.h`); with
  /// `clear_impulses`, without last step's impulses.
  void prepare_joints(float h, bool clear_impulses);
  /// Every joint slot (inactive ones are skipped by the joint passes).
  std::vector<Joint>& solver_joints() { return world_.joints; }
  /// Removes overlap left after the velocity solve, by the world's position correction method.
  void correct_positions();
  /// This step's contacts, sorted by pair.
  std::vector<Contact>& solver_contacts() { return world_.contacts; }
  /// Every body slot (dead slots are never referred to by a contact).
  std::vector<Body>& solver_bodies() { return world_.bodies; }
  /// Scratch of one flag per body slot for the solver's own use (kept to avoid allocating).
  std::vector<std::uint8_t>& solver_body_flags() { return world_.body_flags; }
  /// Scratch for the contacts a bounce plan found bouncing (kept to avoid allocating).
  std::vector<std::uint32_t>& solver_bouncing_contacts() { return world_.bouncing_contacts; }
  /// True when a test asks the bounce and shock stages to skip nothing
  /// (`WorldState::full_bounce_stages`).
  bool full_bounce_stages() const { return world_.full_bounce_stages; }
  /// Scratch for the shock pass's support order (kept to avoid allocating).
  SupportOrder& solver_support_order() { return world_.support_order; }
  /// The compact body states the soft step integrates and solves on (kept to avoid allocating).
  SolverBodies& solver_body_states() { return world_.solver_body_states; }
  /// The soft step's coloured contact blocks (kept to avoid allocating).
  WideContactSolver& solver_wide_contacts() { return world_.wide_contacts; }
  /// The world's workers for stages that share independent work (null: one worker, no task
  /// system).
  WorkerPool* workers() { return pool_; }

 private:
  void set_aside_sleeping_contacts();
  WorldState& world_;
  WorkerPool* pool_;
};

/// A solver method: how one step turns contacts into impulses and motion. Stateless (all
/// memory lives in the contacts), so copies of a world may share one.
class StepSolver {
 public:
  virtual ~StepSolver() = default;
  /// Advances the world by one step of `context.time_step` seconds.
  virtual void step(SolverStages& stages, const SolverContext& context) const = 0;
};

/// The solver of `method` (the registry: one line per method).
std::shared_ptr<const StepSolver> make_step_solver(SolverMethod method);

}  // namespace impulse2d

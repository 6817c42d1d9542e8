#pragma once
/// @file step_solver.h
/// One small interface per solver method: a method drives the stages of a step (collide,
/// integrate, solve contacts, correct positions) in its own order. Adding a method is one
/// file implementing `StepSolver` and one line in `make_step_solver`.

#include "core/body.h"
#include "core/contact.h"
#include "core/solver/contact_visitor.h"
#include "core/settings.h"
#include "core/solver/shock_propagation.h"
#include "core/solver/solver_bodies.h"
#include "core/solver/solver_context.h"
#include "core/solver/wide_contact_solver.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace impulse2d {

/// The pipeline stages a solver method calls; `World` implements them (and times them).
class SolverStages {
 public:
  /// Broad phase, then narrow phase through the jump table: rebuilds `contacts()` with
  /// speculative points for the coming `dt` seconds. `visitor` (may be null) sees each contact
  /// of the new list as the narrow phase finishes it (`contact_visitor.h`).
  virtual void find_contacts(float dt, ContactVisitor* visitor) = 0;
  /// Adds gravity, forces and damping to every awake dynamic body's velocity over `dt` seconds.
  virtual void integrate_velocities(float dt) = 0;
  /// Moves every awake body by its velocity over `dt` seconds (bullets swept if enabled).
  virtual void integrate_positions(float dt) = 0;
  /// Loads `solver_body_states()` from the bodies for this step (after `find_contacts`).
  virtual void begin_solver_bodies() = 0;
  /// `integrate_velocities` on `solver_body_states()` instead of the bodies.
  virtual void integrate_solver_velocities(float dt) = 0;
  /// `integrate_positions` on `solver_body_states()` instead of the bodies (bullets are not
  /// swept: see `sweep_bullets`).
  virtual void integrate_solver_positions(float dt) = 0;
  /// Moves every bullet back to where its motion over the last `dt` seconds first met another
  /// body (continuous collision, when enabled), on the bodies. The soft step sweeps once a
  /// step, after its sub-steps, as its contacts are found once a step: a bullet stopped
  /// within a sub-step would have no contact to meet in the next one.
  virtual void sweep_bullets(float dt) = 0;
  /// Removes overlap left after the velocity solve, by the world's position correction method.
  virtual void correct_positions() = 0;
  /// This step's contacts, sorted by pair.
  virtual std::vector<Contact>& solver_contacts() = 0;
  /// Every body slot (dead slots are never referred to by a contact).
  virtual std::vector<Body>& solver_bodies() = 0;
  /// Scratch of one flag per body slot for the solver's own use (kept to avoid allocating).
  virtual std::vector<std::uint8_t>& solver_body_flags() = 0;
  /// Scratch for the shock pass's support order (kept to avoid allocating).
  virtual SupportOrder& solver_support_order() = 0;
  /// The compact body states the soft step integrates and solves on (kept to avoid allocating).
  virtual SolverBodies& solver_body_states() = 0;
  /// The soft step's coloured contact blocks (kept to avoid allocating).
  virtual WideContactSolver& solver_wide_contacts() = 0;

 protected:
  ~SolverStages() = default;
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

#pragma once
/// @file world_state.h
/// Everything a `World` holds (internal: `world.h` keeps it behind a pointer). The solver
/// stages (`step_solver.h`) and the world's own functions work on it.

#include "core/collide/broad_phase.h"
#include "core/collide/continuous.h"
#include "core/contact.h"
#include "core/settings.h"
#include "core/solver/body_shapes.h"
#include "core/solver/joint_solver.h"
#include "core/solver/shock_propagation.h"
#include "core/solver/sleep.h"
#include "core/solver/solver_bodies.h"
#include "core/solver/wide_contact_solver.h"
#include "core/solver/worker_pool.h"
#include "core/collide/narrow_phase.h"
#include "core/step_stats.h"
#include "core/world.h"
#include "core/world_events.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace impulse2d {

class StepSolver;

/// A world's bodies, contacts, settings and the step's reusable buffers. Copyable: a copy is
/// an independent world that continues to the same states (the solver method is stateless and
/// shared).
struct WorldState {
  WorldSettings settings;
  std::vector<Body> bodies;               ///< slots, indexed by BodyId::index
  std::vector<std::uint8_t> alive;        ///< 1 where the slot holds a body
  std::vector<std::uint32_t> free_slots;  ///< removed slots, reused lowest-first
  int living_body_count = 0;              ///< bodies in living slots

  std::vector<Joint> joints;              ///< slots, indexed by JointId::index
  std::vector<std::uint8_t> joint_alive;  ///< 1 where the slot holds a joint
  std::vector<std::uint32_t> free_joint_slots;  ///< destroyed slots, reused lowest-first
  int living_joint_count = 0;             ///< joints in living slots
  /// (a.index << 32 | b.index), a.index < b.index, of every joint whose bodies must not
  /// collide, ascending (repeats allowed): the broad phase's pairs skip these.
  std::vector<std::uint64_t> unconnected_pairs;

  std::vector<Contact> contacts;          ///< sorted by (a.index, b.index)
  std::vector<Contact> spilled_contacts;  ///< the narrow phase's ring of displaced old contacts (reused)
  std::vector<Contact> sleeping_contacts; ///< pairs with no moving body, sorted by pair
  std::vector<Contact> merged_contacts;   ///< scratch for sleeping_contacts (reused)
  std::shared_ptr<const StepSolver> solver;  ///< made for solver_method (re-made when it changes)
  SolverMethod solver_method = SolverMethod::Accumulated;  ///< what `solver` was made for
  std::vector<float> speculative_reach;   ///< per slot, metres (reused)
  std::vector<Aabb> speculative_bounds;   ///< per slot (reused)
  std::vector<std::uint8_t> body_flags;   ///< per slot, solver scratch (reused)
  std::vector<std::uint32_t> bouncing_contacts;  ///< the bounce plan's contacts (reused)
  /// Test hook: the soft step's bounce and shock stages write the states and impulses out and
  /// read them back in every sub-step, and build the support order afresh, skipping nothing
  /// (the skips must give the same bits).
  bool full_bounce_stages = false;
  SupportOrder support_order;             ///< the shock pass's scratch (reused)
  SolverBodies solver_body_states;        ///< the soft step's compact bodies (reused)
  WideContactSolver wide_contacts;        ///< the soft step's contact arrays (reused)
  BroadPhase broad_phase;                 ///< candidate pairs, persistent between steps
  std::vector<BodyPair> pairs;            ///< broad-phase output (reused)
  SleepIslands sleep_islands;             ///< island bookkeeping (reused)
  BulletSweeper bullet_sweeper;           ///< continuous collision's buffers (reused)
  ContactFilter contact_filter;           ///< the user's, or empty
  WorkerPoolSlot workers;                 ///< `settings.worker_count`'s threads or task system (not copied)
  std::vector<NarrowPhaseJob> narrow_jobs;  ///< the narrow phase's per-pair scratch (reused)

  StepStats stats;                        ///< of the last step
  bool bounds_current = true;  ///< every living body's aabb matches its transform
  std::vector<BodyId> diverged_bodies;    ///< of the last step
  WorldEvents events;                     ///< touches, overlaps and the caller's event buffers
  double time = 0.0;                      ///< simulated seconds
  std::int64_t step_count = 0;            ///< steps taken
  float accumulator = 0.0f;               ///< `World::advance`'s left-over time, seconds

  /// Destroys every joint of body `id` (waking their other bodies).
  void destroy_joints_of(BodyId id);
  /// Rebuilds `unconnected_pairs` from the living joints.
  void rebuild_unconnected_pairs();

  /// The state of `world` (for the core's own functions and white-box tests).
  static const WorldState& of(const World& world) { return *world.state_; }
  /// The state of `world`, writable (for white-box tests that plant a state the API refuses).
  static WorldState& of(World& world) { return *world.state_; }
};

}  // namespace impulse2d

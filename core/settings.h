#pragma once
/// @file settings.h
/// Every method choice of the step, as data: a scene picks them, benchmarks sweep them.

#include "core/material.h"
#include "core/math.h"
#include "core/task_system.h"

#include <optional>
#include <string>
#include <vector>

namespace impulse2d {

/// How contact impulses are computed. Each method has one name, the enumerator's in snake
/// case (`solver_name`: "per_iteration", "accumulated", "soft_step"), in scene files, the lab's
/// labels, the CLI and charts alike.
enum class SolverMethod {
  /// The tutorial's form: each iteration computes a fresh impulse per contact point from the
  /// current relative velocity and applies it (no memory between iterations or steps);
  /// friction uses the static/dynamic Coulomb test against that iteration's normal impulse.
  PerIteration,
  /// Sequential impulses with accumulated (clamped) normal and friction impulses per point,
  /// warm-started from the previous step through persistent contacts (Box2D's form).
  /// Static/dynamic friction: the accumulated tangent impulse is clamped to mu_s * Pn while
  /// the point sticks, and to mu_d * Pn once it slides.
  Accumulated,
  /// Box2D v3's "soft step": collide once per step, then per sub-step integrate velocities,
  /// warm start, solve with soft contacts (a spring-damper of `contact_hertz` and
  /// `contact_damping_ratio` pushing out at most `contact_push_max_speed`, on the separation
  /// recomputed from the current positions), integrate positions and relax (one solve pass
  /// without the soft push-out); restitution is applied once at the end of the step.
  /// Uses `substeps` sub-steps of `velocity_iterations` soft passes each; the soft push-out
  /// replaces position correction, so `position_correction` and its parameters, `block_solver`
  /// and `integrator` (always semi-implicit) are ignored. Friction as for Accumulated.
  SoftStep,
};

/// How overlap left after the velocity solve is removed.
enum class PositionCorrection {
  None,              ///< leave overlap; stacks sink
  LinearProjection,  ///< the tutorial's: move bodies by percent * max(depth - slop, 0) once a step
  /// Nonlinear Gauss-Seidel: iterate on positions, recomputing each point's separation from
  /// the current transforms (Box2D v2.x's position solver); no velocity is added.
  NonlinearGaussSeidel,
};

/// How bodies move between steps.
enum class Integrator {
  ExplicitEuler,      ///< x += v dt, then v += a dt (the contrast; gains energy)
  SemiImplicitEuler,  ///< v += a dt, then x += v dt (symplectic)
};

/// How candidate pairs are found.
enum class BroadPhaseMethod {
  BruteForce,    ///< test every pair of bodies' AABBs: O(n^2), the baseline
  SortAndSweep,  ///< sort AABB lower x, sweep: O(n log n) for scattered scenes
  /// Persistent pairs from dynamic AABB trees (one per body type) of boxes fattened by
  /// `BroadPhase::fat_margin`: only bodies that moved out of their fat box are queried again,
  /// so a scene at rest costs O(n + pairs) a step. Finds the same pairs as the others.
  DynamicTree,
};

/// All settings of a world's step.
struct WorldSettings {
  vec2 gravity{0.0f, -9.81f};  ///< m/s^2
  float time_step = 1.0f / 60.0f;  ///< seconds per step
  /// Each step is split into this many equal sub-steps. The default is the soft step's (Box2D
  /// v3's 4); `settings_for` gives each method its own.
  int substeps = 4;

  /// Impulse scheme. The soft step is the default: of the three it is the most accurate on the
  /// exact-answer suite and the pyramids and the fastest (README, "The engine": "Contacts").
  SolverMethod solver = SolverMethod::SoftStep;
  /// Passes over all contacts per (sub-)step: the soft step makes one soft pass and one relax
  /// pass of this many each (Box2D v3: 1); the accumulated and per-iteration solvers want 16
  /// at one sub-step (16 holds a 30-box stack of rotating boxes that 8 lets fall).
  int velocity_iterations = 1;
  /// Contacts the soft step solves side by side (SoftStep only): 4 (SSE2) or 8 (AVX2, x86-64
  /// CPUs that have it); 0 picks the widest this CPU runs. The result is bit-identical
  /// whichever is chosen (see `wide_contact_solver.h`), so this only changes the speed.
  int solver_lanes = 0;
  bool warm_starting = true;    ///< carry accumulated impulses over (Accumulated only)
  /// Solve the two normal impulses of a 2-point manifold together as a 2x2 linear
  /// complementarity problem (Box2D's block solver) instead of one after the other, which keeps
  /// stacks from rocking (Accumulated only).
  bool block_solver = true;
  /// Shock propagation: after the velocity iterations, one more pass over the contacts that
  /// carry load, from the ground up, with the lower body of each held fixed (see
  /// `shock_propagation.h`). Holds heavy bodies on light ones (1:1000) where plain iterations
  /// let the light one be squeezed out (Accumulated).
  bool shock_propagation = true;

  /// Speculative contacts: pairs closer than this (metres), plus the distance their bodies can
  /// cover in the coming step, already get contact points with a negative depth (the gap), and
  /// the solvers let them approach by at most that gap per step, so a landing body is caught at
  /// the surface and touching bodies never free-fall for a step. 0 turns speculation off (only
  /// overlapping shapes make contacts).
  float speculative_margin = 0.02f;
  /// Contact recycling (see `contact_recycle.h`): a pair whose relative pose moved less than
  /// this (metres) since its manifold was computed keeps that manifold, with separations
  /// updated from its anchors, instead of being collided afresh. 0 collides every step.
  /// Box2D v3's default is 10 linear slops (5 cm).
  float contact_recycle_distance = 0.05f;

  PositionCorrection position_correction = PositionCorrection::NonlinearGaussSeidel;  ///< method
  int position_iterations = 3;      ///< passes for NonlinearGaussSeidel
  float correction_percent = 0.4f;  ///< fraction of overlap removed per pass (tutorial 0.2-0.8)
  float slop = 0.01f;               ///< metres of overlap allowed without correction
  float max_correction = 0.2f;      ///< metres a single NGS correction may move a point

  /// SoftStep: stiffness of the soft contact, Hz (capped at a quarter of the sub-step rate;
  /// contacts with a static or kinematic body use twice it).
  float contact_hertz = 30.0f;
  /// SoftStep: damping ratio of the soft contact (1 = critical; Box2D v3 uses 10).
  float contact_damping_ratio = 10.0f;
  /// SoftStep: fastest speed (m/s) at which the soft contact pushes overlapping bodies apart.
  float contact_push_max_speed = 3.0f;

  /// Approach speed (m/s) below which a contact is treated as resting (restitution 0), so
  /// stacks settle. Set 0 to bounce at any speed.
  float restitution_threshold = 1.0f;
  FrictionMixing friction_mixing = FrictionMixing::GeometricMean;      ///< friction rule
  RestitutionMixing restitution_mixing = RestitutionMixing::Maximum;   ///< restitution rule

  Integrator integrator = Integrator::SemiImplicitEuler;  ///< motion integration
  BroadPhaseMethod broad_phase = BroadPhaseMethod::DynamicTree;  ///< pair finding

  bool enable_friction = true;     ///< off: skip all tangent impulses
  bool enable_restitution = true;  ///< off: every contact is inelastic
  bool enable_rotation = true;     ///< off: no body rotates (angular terms skipped)
  bool enable_sleeping = false;    ///< put bodies at rest to sleep
  /// Sweep bodies marked `is_bullet` so they cannot tunnel through thin bodies (continuous
  /// collision); off, bullets move like any other body.
  bool enable_continuous = true;
  float sleep_linear_speed = 0.05f;  ///< m/s below which a body may sleep
  float sleep_angular_speed = 0.05f; ///< rad/s below which a body may sleep
  float time_to_sleep = 0.5f;        ///< seconds a body must stay slow before it sleeps
  float max_linear_speed = 400.0f;   ///< m/s clamp against blow-ups

  /// Threads that share a step, the calling one included: 1..64. Without a `task_system`,
  /// above 1 the world starts `worker_count - 1` threads of its own on its first step (joined
  /// when it is destroyed; a copy starts its own), and the narrow phase's collisions, the soft
  /// step's body integration and the blocks of each contact colour, and the bounds update run on
  /// them (docs/engine.md, "Threads"). With a `task_system`, the number of workers it has: the
  /// world starts no threads. The state after every step is bit-identical whatever the count;
  /// only the speed changes. Not saved in snapshots or scene files: it is how to run, not what
  /// to simulate.
  int worker_count = 1;
  /// The caller's threads (`task_system.h`): when `enqueue` and `finish` are set, every shared
  /// stage of the step runs through them instead of threads of the world's own; the default
  /// (both null) is the world's own workers. Bit-identical results either way. Not saved in
  /// snapshots or scene files; a copied world uses the same one, a restored world keeps its own.
  TaskSystem task_system;
};

/// The default settings with `method` at the sub-steps and passes it is measured at:
/// SoftStep 4 sub-steps of 1 pass (the default), Accumulated and PerIteration 1 step
/// of 16 passes.
WorldSettings settings_for(SolverMethod method);

/// The method's one name (scene files, lab labels, CLI, charts): "per_iteration",
/// "accumulated", "soft_step".
const char* solver_name(SolverMethod method);

/// Every solver method, in the order of `SolverMethod`.
const std::vector<SolverMethod>& solver_methods();

/// The method that a spelling other than its name stands for: the lab's old labels ("iter",
/// "acc", "soft") and the C++ enumerators ("PerIteration", "AccumulatedImpulses", ...), so
/// that a scene reader can refuse it by naming the right spelling; empty for any other text.
std::optional<SolverMethod> retired_solver_name(const std::string& name);

/// Throws `Error` naming the field unless every setting is finite and in range
/// (time_step > 0, substeps >= 1, iterations >= 0, 0 <= percent <= 1, slop >= 0, ...) and the
/// task system is whole (`enqueue` and `finish` both set or both null; no `user_context`
/// without them).
void validate_settings(const WorldSettings& settings);

}  // namespace impulse2d

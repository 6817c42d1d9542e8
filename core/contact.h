#pragma once
/// @file contact.h
/// A persistent contact between two bodies: the manifold plus the solver's per-point memory.

#include "core/body.h"
#include "core/manifold.h"

#include <cstdint>

namespace impulse2d {

/// Inverse masses (1/kg) and inverse inertias (1/(kg m^2)) of a contact's two bodies, with the
/// world's rotation switches applied; resolved once per step when the contact is prepared.
struct PairMass {
  float inverse_mass_a = 0.0f;     ///< 1/kg
  float inverse_mass_b = 0.0f;     ///< 1/kg
  float inverse_inertia_a = 0.0f;  ///< 1/(kg m^2), 0 when A does not rotate
  float inverse_inertia_b = 0.0f;  ///< 1/(kg m^2), 0 when B does not rotate
};

/// What the wide solver solves a two-point manifold with, found from the points' anchors and
/// effective masses and kept with them while they are kept (`Contact::kept_pair_solve`).
struct PairSolve {
  /// False when the points' normal effective-mass matrix is too ill-conditioned to solve them
  /// as a pair (they are then solved one after the other, and the masses below are 0).
  bool solvable = false;
  /// Inverse (kg) of the two points' normal effective-mass matrix, row by row (the matrix is
  /// symmetric).
  float mass_00 = 0.0f;
  float mass_01 = 0.0f;  ///< off-diagonal of that inverse, kg
  float mass_11 = 0.0f;  ///< second diagonal entry of that inverse, kg
  /// Effective mass (kg) along the tangent at the middle of the two points.
  float middle_tangent_mass = 0.0f;
};

/// The solver's state for one manifold point.
struct ContactPoint {
  vec2 point{0.0f, 0.0f};      ///< world position, metres, midway between the two surfaces
  vec2 anchor_a{0.0f, 0.0f};   ///< point relative to A's centre of mass, metres
  vec2 anchor_b{0.0f, 0.0f};   ///< point relative to B's centre of mass, metres
  /// A's core point in A's frame, metres: A's surface point moved in along the normal by A's
  /// rounding (a circle's: its centre), so that it stays a fixed point of A as A turns: the
  /// separation tracked from it does not grow when a curved body rolls.
  vec2 local_anchor_a{0.0f, 0.0f};
  vec2 local_anchor_b{0.0f, 0.0f};  ///< B's core point in B's frame, metres (as A's)
  /// Sum (m) of the two shapes' roundings: the separation is the core points' offset along
  /// the normal less this.
  float rounding = 0.0f;
  /// Penetration at detection, metres: positive when overlapping, negative for a speculative
  /// point (the gap the bodies may still close).
  float depth = 0.0f;
  std::uint32_t feature_id = 0;     ///< identifies the point across steps
  float normal_impulse = 0.0f;      ///< accumulated (or last) normal impulse, N s
  float tangent_impulse = 0.0f;     ///< accumulated (or last) friction impulse, N s
  float normal_mass = 0.0f;         ///< effective mass along the normal, kg
  float tangent_mass = 0.0f;        ///< effective mass along the tangent, kg
  /// The smallest relative normal velocity (m/s) the velocity solve allows: -gap/h for a
  /// speculative point (it may close its gap, no more), 0 for a touching one, and for a point
  /// that bounces in this (sub-)step the speed that leaves it where the bounce would have
  /// put it at the end of the step (see `contact_bounce.h`).
  float velocity_bias = 0.0f;
  /// True when the point bounces in this (sub-)step: after positions move, its relative normal
  /// velocity is raised to `bounce_speed`.
  bool bouncing = false;
  /// Separating speed (m/s) a bouncing point leaves the step with.
  float bounce_speed = 0.0f;
  /// True once the point's bounce was applied: its accumulated impulses are a collision's, not
  /// a resting contact's, so they are not warm-started into the next (sub-)step.
  bool bounced = false;
  /// True when the point approached faster at the start of the step than gravity alone brings
  /// a resting contact in a step (2 |g| h): an impact, not a load. The soft step stops it
  /// rigidly (a soft catch lets a fast body through a thin wall), and, like a bounce's, its
  /// impulse is not warm-started into the next step, where it would launch the body off the
  /// surface it landed on.
  bool caught = false;
  /// True when the point is elastic (restitution > 0), one of its bodies bounces in this
  /// (sub-)step, and it neither closes its gap within the step at the velocities the step
  /// began with, overlaps by more than the slop, nor carries impulse from the last step: it
  /// sits out this step's solve, so an impact travels along a touching elastic row one contact
  /// per step (Newton's cradle) instead of being shared by the whole row at once, and a bounce
  /// that drives a body into a third one makes a second bounce next step instead of an
  /// inelastic stop inside this solve (which would lose energy).
  bool waiting = false;
  bool friction_at_limit = false;   ///< the last friction pass was clamped by the Coulomb limit
  /// Contact recycling (`contact_recycle.h`): the point as the manifold last found it, in A's
  /// frame, metres.
  vec2 recycle_anchor_a{0.0f, 0.0f};
  /// The same point in B's frame, metres.
  vec2 recycle_anchor_b{0.0f, 0.0f};
  /// The point's separation when the manifold was last found, metres (> 0 apart).
  float base_separation = 0.0f;
  /// Offset (m, along the contact's tangent) of B's recycle anchor from A's where the point
  /// last stuck: the soft step's friction pulls the point back to it while the contact sticks
  /// (see `friction_drift`), and moves it along while the point slips.
  float stick_offset = 0.0f;
};

/// Where a contact's bodies stood when its manifold was last computed, for contact recycling.
struct ManifoldPose {
  /// B's centre in A's frame, metres (A's centre in B's frame when only B is static)
  vec2 relative_position{0.0f, 0.0f};
  Rotation rotation_a;                 ///< A's rotation
  Rotation rotation_b;                 ///< B's rotation
};

/// A touching (or, with a speculative margin, nearly touching) pair of bodies (of shapes, for
/// compound bodies). Body A has the smaller slot index.
struct Contact {
  BodyId body_a;   ///< first body (smaller index)
  BodyId body_b;   ///< second body
  /// Which of A's shapes touches (0 unless A is a compound body): a pair of compound bodies
  /// has a contact per pair of shapes, sorted after the bodies by (child_a, child_b).
  std::uint16_t child_a = 0;
  std::uint16_t child_b = 0;  ///< which of B's shapes touches (0 unless B is compound)
  // The fields every walk over the list reads (events, islands, colouring, impulses) come
  // first, so that such a walk touches as few cache lines of each contact as it can.
  /// False when a contact filter (or `World::set_contact_enabled`) rejected the pair; the
  /// decision is kept while the shapes overlap (so one-way platforms do not pop bodies
  /// through) and taken afresh once they are more than a millimetre apart.
  bool enabled = true;
  bool recycled = false;     ///< this step kept last step's manifold (see contact_recycle.h)
  /// The contact touches in this step, as contact events count it (`touches_in_step`):
  /// recorded by prepare when contact events are on, while the contact is in the cache; valid
  /// for the awake, enabled contacts of the step just taken (set-aside ones are judged afresh).
  bool touching = false;
  /// True while the points' `anchor_a/b`, `normal_mass` and `tangent_mass` are those prepare
  /// found for this kept manifold (see contact_recycle.h) and this `mass`: prepared again
  /// while the manifold is kept, the contact keeps them instead of computing the same values
  /// anew. False for a manifold computed afresh; cleared whenever `mass` changes.
  bool kept_masses = false;
  vec2 normal{0.0f, 0.0f};   ///< unit, from A to B
  int point_count = 0;       ///< 1 or 2
  PairMass mass;             ///< the two bodies' inverse masses, resolved at prepare
  ContactPoint points[max_manifold_points];  ///< the first `point_count` are valid
  float static_friction = 0.0f;   ///< mixed coefficient
  float dynamic_friction = 0.0f;  ///< mixed coefficient
  float restitution = 0.0f;       ///< mixed coefficient
  /// Coulomb state of the contact as a whole: false while it sticks (friction limit
  /// mu_s * Pn), true once the friction it needed reached the static limit at every point
  /// (limit mu_d * Pn) or when it began with its surfaces slipping; back to false when its
  /// relative tangential speed returns to rest.
  bool sliding = false;
  /// True while `pair_solve` holds what the wide solver found for these effective masses
  /// (prepare clears it whenever it computes them afresh, see `kept_masses`).
  bool kept_pair_solve = false;
  /// Relative acceleration (m/s^2) with which applied forces and gravity drive the bodies
  /// together along the normal (positive: closing); used to time a bounce within the step.
  float approach_acceleration = 0.0f;
  /// Mean relative tangential velocity (m/s, along the normal turned clockwise) of the points
  /// at prepare, before this step's forces: slip the contact carried into the step.
  float start_slip = 0.0f;
  /// Sum (N s) of the points' normal impulses at prepare: the load carried into the step.
  float start_load = 0.0f;
  /// Consecutive steps (0..2) that ended with every point at the static limit and the slip
  /// growing; the contact breaks loose at 2 (one such step can be a cold-started solve).
  std::uint8_t steps_at_static_limit = 0;
  /// |mean relative tangential velocity| (m/s) at the end of last step's solve if that step
  /// ended with every point at the static limit, else -1: a slip that grows from one such
  /// step to the next grows under the full static limit even when an impulse applied between
  /// the steps (a per-step push) makes each step start faster than it ends.
  float limit_slip = -1.0f;
  ManifoldPose manifold_pose;  ///< the bodies' pose when the manifold was last computed
  PairSolve pair_solve;        ///< the wide solver's values of a two-point manifold
};

/// True when `a` comes before `b` in the order contact lists keep: by A's slot, B's slot, then
/// A's and B's shape.
inline bool contact_less(const Contact& a, const Contact& b) {
  if (a.body_a.index != b.body_a.index) return a.body_a.index < b.body_a.index;
  if (a.body_b.index != b.body_b.index) return a.body_b.index < b.body_b.index;
  if (a.child_a != b.child_a) return a.child_a < b.child_a;
  return a.child_b < b.child_b;
}

}  // namespace impulse2d

#pragma once
/// @file wide_contact_kernel.h
/// The soft step's contact passes on `ContactBlock`s, written once for any lane count with the
/// compilers' vector extensions (GCC and Clang): every operation works lane by lane in IEEE
/// single precision, no fused multiply-add, so a block's lanes give the same bits whether the
/// machine runs 4 or 8 of them per instruction.
///
/// Included only by the kernel files (`wide_contact_kernel_4.cpp`, `wide_contact_kernel_8.cpp`),
/// each compiled for its own instruction set. Everything here has internal linkage (the
/// unnamed namespace) and calls no inline function of another header, so the linker never
/// merges an AVX2 copy of a function into code that runs on a CPU without AVX2.
///
/// The passes (Box2D v3's soft step, per point of each contact):
/// - Normal: the separation s (m) is recomputed from the bodies' current poses through the
///   point's surface anchors. Apart (s > 0) the bodies may close the gap within the sub-step
///   (vn >= -s / h, a speculative contact); overlapping, the biased pass pushes out softly at
///   min(bias_rate |s|, push_max_speed) (twice as stiff against a body contacts never move);
///   the relax pass is rigid, adds no push-out speed and leaves points still apart alone (so
///   no push-out speed stays in the velocities). A point bouncing in this sub-step keeps its
///   bounce's rigid target (`contact_bounce.h`); a waiting one sits the sub-step out. Normal
///   impulses stay >= 0.
/// - Friction, relax pass: Coulomb, clamped to mu_s Pn while the contact sticks and mu_d Pn once
///   it slides, against normal impulses without the soft push-out (so the push-out never raises
///   the limit). `friction_at_limit` records where the clamp acted.
/// - Friction, biased pass, sticking contacts only: each point's tangential speed is driven to
///   the speed that takes back its drift from where it stuck (`stick_*`) at the contact's own
///   `bias_rate`, no faster than push_max_speed, within mu_s Pn. Without it a loaded point
///   slips a little every sub-step (the Gauss-Seidel residual) and the slips add up: the
///   100-row pyramid spread 12 cm sideways in 500 steps, 0.5 cm with it. Tried and rejected:
///   the pull-back in the relax pass (the stick/slip state read it as slip and broke resting
///   contacts loose) and a soft (spring-damper) friction (weaker: the pyramid sank 10 cm more).
/// - Warm starting applies the accumulated impulses, normal and tangent, first.

#include "core/solver/contact_block.h"
#include "core/solver/solver_body.h"

#include <cstdint>
#include <cstring>

#if defined(__AVX2__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace impulse2d {
namespace {

template <int Lanes>
struct LaneTypes;
template <>
struct LaneTypes<4> {
  typedef float Floats __attribute__((vector_size(16)));
  typedef std::int32_t Masks __attribute__((vector_size(16)));
};
template <>
struct LaneTypes<8> {
  typedef float Floats __attribute__((vector_size(32)));
  typedef std::int32_t Masks __attribute__((vector_size(32)));
};

template <class Vector>
Vector load_lanes(const void* source) {
  Vector value;
  std::memcpy(&value, source, sizeof value);
  return value;
}

template <class Vector>
void store_lanes(void* target, Vector value) {
  std::memcpy(target, &value, sizeof value);
}

// a where mask is set, b elsewhere (every mask lane is all ones or all zeros).
template <class Floats, class Masks>
Floats select_lanes(Masks mask, Floats a, Floats b) {
#if defined(__AVX2__)
  if constexpr (sizeof(Masks) == 32) return (Floats)_mm256_blendv_ps((__m256)b, (__m256)a, (__m256)mask);
#endif
  return (Floats)(((Masks)a & mask) | ((Masks)b & ~mask));
}

// True when any lane of `mask` is set (every mask lane is all ones or all zeros).
template <class Masks>
bool any_lane(Masks mask) {
#if defined(__AVX2__)
  if constexpr (sizeof(Masks) == 32) return _mm256_movemask_ps((__m256)mask) != 0;
#endif
#if defined(__SSE2__)
  if constexpr (sizeof(Masks) == 16) return _mm_movemask_ps((__m128)mask) != 0;
#endif
  std::int32_t any = 0;
  for (std::size_t lane = 0; lane < sizeof(Masks) / sizeof(std::int32_t); ++lane) any |= mask[lane];
  return any != 0;
}

template <class Floats>
Floats splat(float value) {
  Floats lanes = {};
  return lanes + value;
}

// The velocities and poses of one side's bodies, lane by lane (the angle only to write each
// body's first 16 bytes back whole).
template <int Lanes>
struct BodyLanes {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  Floats velocity_x, velocity_y, angular_velocity, angle;
  Floats position_x, position_y, cosine, sine;
};

// The bodies of a block side, lane by lane: each 32-byte SolverBody is loaded whole and the
// rows are transposed into fields with shuffles (scalar inserts would go through the stack and
// stall on store forwarding). __builtin_shufflevector: GCC >= 12 and Clang. The 8-lane form
// exists only where it is compiled for AVX2.
#if defined(__AVX2__)
inline __attribute__((always_inline)) BodyLanes<8> gather_8_bodies(const SolverBody* bodies,
                                                                   const std::int32_t* slots) {
  typedef LaneTypes<8>::Floats F;
  F r[8];
  for (int lane = 0; lane < 8; ++lane) r[lane] = load_lanes<F>(&bodies[slots[lane]]);
  F t[8];
  for (int i = 0; i < 4; ++i) {
    t[2 * i] = __builtin_shufflevector(r[2 * i], r[2 * i + 1], 0, 8, 1, 9, 4, 12, 5, 13);
    t[2 * i + 1] = __builtin_shufflevector(r[2 * i], r[2 * i + 1], 2, 10, 3, 11, 6, 14, 7, 15);
  }
  F u[8];
  for (int i = 0; i < 2; ++i) {
    const F& low_a = t[4 * i];
    const F& high_a = t[4 * i + 1];
    const F& low_b = t[4 * i + 2];
    const F& high_b = t[4 * i + 3];
    u[4 * i] = __builtin_shufflevector(low_a, low_b, 0, 1, 8, 9, 4, 5, 12, 13);
    u[4 * i + 1] = __builtin_shufflevector(low_a, low_b, 2, 3, 10, 11, 6, 7, 14, 15);
    u[4 * i + 2] = __builtin_shufflevector(high_a, high_b, 0, 1, 8, 9, 4, 5, 12, 13);
    u[4 * i + 3] = __builtin_shufflevector(high_a, high_b, 2, 3, 10, 11, 6, 7, 14, 15);
  }
  // u[k] holds field k of bodies 0-3 then field k + 4 of bodies 0-3; u[4 + k] bodies 4-7.
  BodyLanes<8> lanes;
  lanes.velocity_x = __builtin_shufflevector(u[0], u[4], 0, 1, 2, 3, 8, 9, 10, 11);
  lanes.velocity_y = __builtin_shufflevector(u[1], u[5], 0, 1, 2, 3, 8, 9, 10, 11);
  lanes.angular_velocity = __builtin_shufflevector(u[2], u[6], 0, 1, 2, 3, 8, 9, 10, 11);
  lanes.angle = __builtin_shufflevector(u[3], u[7], 0, 1, 2, 3, 8, 9, 10, 11);
  lanes.position_x = __builtin_shufflevector(u[0], u[4], 4, 5, 6, 7, 12, 13, 14, 15);
  lanes.position_y = __builtin_shufflevector(u[1], u[5], 4, 5, 6, 7, 12, 13, 14, 15);
  lanes.cosine = __builtin_shufflevector(u[2], u[6], 4, 5, 6, 7, 12, 13, 14, 15);
  lanes.sine = __builtin_shufflevector(u[3], u[7], 4, 5, 6, 7, 12, 13, 14, 15);
  return lanes;
}
#endif

inline __attribute__((always_inline)) BodyLanes<4> gather_4_bodies(const SolverBody* bodies,
                                                                   const std::int32_t* slots) {
  typedef LaneTypes<4>::Floats F;
  F velocity[4], pose[4];  // per lane: (vx, vy, w, angle) and (px, py, cos, sin)
  for (int lane = 0; lane < 4; ++lane) {
    const SolverBody* body = &bodies[slots[lane]];
    velocity[lane] = load_lanes<F>(&body->velocity_x);
    pose[lane] = load_lanes<F>(&body->position_x);
  }
  BodyLanes<4> lanes;
  F* fields[2][4] = {{&lanes.velocity_x, &lanes.velocity_y, &lanes.angular_velocity, &lanes.angle},
                     {&lanes.position_x, &lanes.position_y, &lanes.cosine, &lanes.sine}};
  const F* rows[2] = {velocity, pose};
  for (int half = 0; half < 2; ++half) {
    const F* r = rows[half];
    const F t0 = __builtin_shufflevector(r[0], r[1], 0, 4, 1, 5);
    const F t1 = __builtin_shufflevector(r[0], r[1], 2, 6, 3, 7);
    const F t2 = __builtin_shufflevector(r[2], r[3], 0, 4, 1, 5);
    const F t3 = __builtin_shufflevector(r[2], r[3], 2, 6, 3, 7);
    *fields[half][0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    *fields[half][1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    *fields[half][2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    *fields[half][3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
  }
  return lanes;
}

template <int Lanes>
inline __attribute__((always_inline)) BodyLanes<Lanes> gather_bodies(const SolverBody* bodies,
                                                                     const std::int32_t* slots) {
#if defined(__AVX2__)
  if constexpr (Lanes == 8) return gather_8_bodies(bodies, slots);
#endif
  if constexpr (Lanes == 4) return gather_4_bodies(bodies, slots);
}

// Each lane's first 16 bytes of its SolverBody (velocity, angular velocity and the angle as
// gathered), transposed back from fields to rows with shuffles: row[lane].
typedef float BodyRow __attribute__((vector_size(16)));

#if defined(__AVX2__)
inline __attribute__((always_inline)) void velocity_rows_8(const BodyLanes<8>& lanes,
                                                           BodyRow* rows) {
  typedef LaneTypes<8>::Floats F;
  const F t0 = __builtin_shufflevector(lanes.velocity_x, lanes.velocity_y, 0, 8, 1, 9, 4, 12, 5, 13);
  const F t1 = __builtin_shufflevector(lanes.velocity_x, lanes.velocity_y, 2, 10, 3, 11, 6, 14, 7, 15);
  const F t2 = __builtin_shufflevector(lanes.angular_velocity, lanes.angle, 0, 8, 1, 9, 4, 12, 5, 13);
  const F t3 = __builtin_shufflevector(lanes.angular_velocity, lanes.angle, 2, 10, 3, 11, 6, 14, 7, 15);
  const F r04 = __builtin_shufflevector(t0, t2, 0, 1, 8, 9, 4, 5, 12, 13);
  const F r15 = __builtin_shufflevector(t0, t2, 2, 3, 10, 11, 6, 7, 14, 15);
  const F r26 = __builtin_shufflevector(t1, t3, 0, 1, 8, 9, 4, 5, 12, 13);
  const F r37 = __builtin_shufflevector(t1, t3, 2, 3, 10, 11, 6, 7, 14, 15);
  rows[0] = __builtin_shufflevector(r04, r04, 0, 1, 2, 3);
  rows[4] = __builtin_shufflevector(r04, r04, 4, 5, 6, 7);
  rows[1] = __builtin_shufflevector(r15, r15, 0, 1, 2, 3);
  rows[5] = __builtin_shufflevector(r15, r15, 4, 5, 6, 7);
  rows[2] = __builtin_shufflevector(r26, r26, 0, 1, 2, 3);
  rows[6] = __builtin_shufflevector(r26, r26, 4, 5, 6, 7);
  rows[3] = __builtin_shufflevector(r37, r37, 0, 1, 2, 3);
  rows[7] = __builtin_shufflevector(r37, r37, 4, 5, 6, 7);
}
#endif

inline __attribute__((always_inline)) void velocity_rows_4(const BodyLanes<4>& lanes,
                                                           BodyRow* rows) {
  const BodyRow t0 = __builtin_shufflevector(lanes.velocity_x, lanes.velocity_y, 0, 4, 1, 5);
  const BodyRow t1 = __builtin_shufflevector(lanes.velocity_x, lanes.velocity_y, 2, 6, 3, 7);
  const BodyRow t2 = __builtin_shufflevector(lanes.angular_velocity, lanes.angle, 0, 4, 1, 5);
  const BodyRow t3 = __builtin_shufflevector(lanes.angular_velocity, lanes.angle, 2, 6, 3, 7);
  rows[0] = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  rows[1] = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  rows[2] = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  rows[3] = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// Writes the velocities back to the bodies the contacts move (`moves` set in the lane's flags;
// never to a static, kinematic or unused lane's slot, which other lanes may share), 16 bytes
// a body: the velocities and the angle it had (no lane of a block changes another's body).
template <int Lanes>
inline __attribute__((always_inline)) void scatter_velocities(SolverBody* bodies,
                                                              const std::int32_t* slots,
                                                              const std::int32_t* flags,
                                                              std::int32_t moves,
                                                              const BodyLanes<Lanes>& lanes) {
  BodyRow rows[Lanes];
#if defined(__AVX2__)
  if constexpr (Lanes == 8) velocity_rows_8(lanes, rows);
#endif
  if constexpr (Lanes == 4) velocity_rows_4(lanes, rows);
#pragma GCC unroll 8
  for (int lane = 0; lane < Lanes; ++lane) {
    if (!(flags[lane] & moves)) continue;
    store_lanes(&bodies[slots[lane]].velocity_x, rows[lane]);
  }
}

// The lanes where `flag` (a single bit) is set in `flags`: -1 there, 0 elsewhere (an equality
// test against the bit: one comparison, where `!= 0` takes a comparison and a negation).
template <class Masks>
Masks flag_lanes(Masks flags, std::int32_t flag) {
  const Masks bit = Masks{} + flag;
  return (flags & bit) == bit;
}

// The block's per-contact constants and both sides' bodies.
template <int Lanes>
struct BlockState {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  typedef typename LaneTypes<Lanes>::Masks Masks;
  BodyLanes<Lanes> a, b;
  Masks flags;
  Floats normal_x, normal_y, tangent_x, tangent_y;
  Floats inverse_mass_a, inverse_mass_b, inverse_inertia_a, inverse_inertia_b;

  BlockState(const ContactBlock<Lanes>& block, const SolverBody* bodies)
      : a(gather_bodies<Lanes>(bodies, block.body_a)),
        b(gather_bodies<Lanes>(bodies, block.body_b)),
        flags(load_lanes<Masks>(block.flags)),
        normal_x(load_lanes<Floats>(block.normal_x)),
        normal_y(load_lanes<Floats>(block.normal_y)),
        tangent_x(normal_y),
        tangent_y(-normal_x),
        inverse_mass_a(load_lanes<Floats>(block.inverse_mass_a)),
        inverse_mass_b(load_lanes<Floats>(block.inverse_mass_b)),
        inverse_inertia_a(load_lanes<Floats>(block.inverse_inertia_a)),
        inverse_inertia_b(load_lanes<Floats>(block.inverse_inertia_b)) {}

  // B's velocity at the point relative to A's, along (direction_x, direction_y), m/s.
  Floats relative_speed(Floats anchor_ax, Floats anchor_ay, Floats anchor_bx, Floats anchor_by,
                        Floats direction_x, Floats direction_y) const {
    const Floats velocity_bx = b.velocity_x + -b.angular_velocity * anchor_by;
    const Floats velocity_by = b.velocity_y + b.angular_velocity * anchor_bx;
    const Floats velocity_ax = a.velocity_x + -a.angular_velocity * anchor_ay;
    const Floats velocity_ay = a.velocity_y + a.angular_velocity * anchor_ax;
    return (velocity_bx - velocity_ax) * direction_x + (velocity_by - velocity_ay) * direction_y;
  }

  // Applies the impulse (N s) to B at its anchor and the opposite to A.
  void apply(Floats anchor_ax, Floats anchor_ay, Floats anchor_bx, Floats anchor_by,
             Floats impulse_x, Floats impulse_y) {
    a.velocity_x -= impulse_x * inverse_mass_a;
    a.velocity_y -= impulse_y * inverse_mass_a;
    a.angular_velocity -= inverse_inertia_a * (anchor_ax * impulse_y - anchor_ay * impulse_x);
    b.velocity_x += impulse_x * inverse_mass_b;
    b.velocity_y += impulse_y * inverse_mass_b;
    b.angular_velocity += inverse_inertia_b * (anchor_bx * impulse_y - anchor_by * impulse_x);
  }

  // Applies two impulses (N s) at once, each to B at its anchor and the opposite to A: their
  // sums, so the result does not depend on which point is named first (a mirror image of a
  // contact gets the mirror image of its velocities, bit for bit).
  void apply_pair(const Floats (&anchor_ax)[2], const Floats (&anchor_ay)[2],
                  const Floats (&anchor_bx)[2], const Floats (&anchor_by)[2],
                  const Floats (&impulse_x)[2], const Floats (&impulse_y)[2]) {
    const Floats total_x = impulse_x[0] + impulse_x[1];
    const Floats total_y = impulse_y[0] + impulse_y[1];
    const Floats moment_a = (anchor_ax[0] * impulse_y[0] - anchor_ay[0] * impulse_x[0]) +
                            (anchor_ax[1] * impulse_y[1] - anchor_ay[1] * impulse_x[1]);
    const Floats moment_b = (anchor_bx[0] * impulse_y[0] - anchor_by[0] * impulse_x[0]) +
                            (anchor_bx[1] * impulse_y[1] - anchor_by[1] * impulse_x[1]);
    a.velocity_x -= total_x * inverse_mass_a;
    a.velocity_y -= total_y * inverse_mass_a;
    a.angular_velocity -= inverse_inertia_a * moment_a;
    b.velocity_x += total_x * inverse_mass_b;
    b.velocity_y += total_y * inverse_mass_b;
    b.angular_velocity += inverse_inertia_b * moment_b;
  }

  // Offset (m) along (direction_x, direction_y) of B's local point from A's, both placed by
  // the bodies' current poses; the local points' coordinates are lane arrays of a block.
  Floats offset_along(const float* ax, const float* ay, const float* bx, const float* by,
                      Floats direction_x, Floats direction_y) const {
    const Floats local_ax = load_lanes<Floats>(ax), local_ay = load_lanes<Floats>(ay);
    const Floats local_bx = load_lanes<Floats>(bx), local_by = load_lanes<Floats>(by);
    const Floats world_ax = (a.cosine * local_ax - a.sine * local_ay) + a.position_x;
    const Floats world_ay = (a.sine * local_ax + a.cosine * local_ay) + a.position_y;
    const Floats world_bx = (b.cosine * local_bx - b.sine * local_by) + b.position_x;
    const Floats world_by = (b.sine * local_bx + b.cosine * local_by) + b.position_y;
    return (world_bx - world_ax) * direction_x + (world_by - world_ay) * direction_y;
  }

  void store(const ContactBlock<Lanes>& block, SolverBody* bodies) const {
    scatter_velocities<Lanes>(bodies, block.body_a, block.flags, block_moves_a, a);
    scatter_velocities<Lanes>(bodies, block.body_b, block.flags, block_moves_b, b);
  }
};

// A lane's softness (`Softness`' fields): the static one where the contact is against a body
// it never moves, the dynamic one elsewhere.
template <int Lanes>
struct SoftnessLanes {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  Floats bias_rate, mass_scale, impulse_scale;

  SoftnessLanes(const BlockState<Lanes>& state, const WidePassSettings& pass) {
    const typename LaneTypes<Lanes>::Masks fixed = flag_lanes(state.flags, block_against_fixed);
    bias_rate = select_lanes(fixed, splat<Floats>(pass.static_softness.bias_rate),
                             splat<Floats>(pass.dynamic_softness.bias_rate));
    mass_scale = select_lanes(fixed, splat<Floats>(pass.static_softness.mass_scale),
                              splat<Floats>(pass.dynamic_softness.mass_scale));
    impulse_scale = select_lanes(fixed, splat<Floats>(pass.static_softness.impulse_scale),
                                 splat<Floats>(pass.dynamic_softness.impulse_scale));
  }
};

// v clamped to [low, high] (std::clamp's comparisons, lane by lane).
template <class Floats>
Floats clamp_lanes(Floats value, Floats low, Floats high) {
  return select_lanes(value < low, low, select_lanes(high < value, high, value));
}

// What the soft step's normal constraint of one point slot asks in this pass.
template <int Lanes>
struct NormalTarget {
  typename LaneTypes<Lanes>::Masks active;        // lanes whose point takes part
  typename LaneTypes<Lanes>::Floats target_speed;  // m/s: relative normal speed sought
  typename LaneTypes<Lanes>::Floats mass_scale;    // softness' share of the effective mass
  typename LaneTypes<Lanes>::Floats impulse_scale; // softness' share of the old impulse
};

// The target of point slot `slot` (0 or 1), whose separation (m) is `separation`.
template <int Lanes>
NormalTarget<Lanes> normal_target(const BlockState<Lanes>& state,
                                  const SoftnessLanes<Lanes>& softness, int slot,
                                  typename LaneTypes<Lanes>::Floats separation,
                                  const BlockPointSolve<Lanes>& solve,
                                  const WidePassSettings& pass) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  typedef typename LaneTypes<Lanes>::Masks Masks;
  const Floats zero = {};
  const Floats one = splat<Floats>(1.0f);
  const Masks present = flag_lanes(state.flags, block_point_present << slot);
  const Masks waiting = flag_lanes(state.flags, block_point_waiting << slot);
  const Masks bouncing = flag_lanes(state.flags, block_point_bouncing << slot);
  const Masks caught = flag_lanes(state.flags, block_point_caught << slot);
  const Floats velocity_bias = load_lanes<Floats>(solve.velocity_bias);
  const Masks apart = separation > zero;

  NormalTarget<Lanes> target;
  target.active = present & ~waiting;
  if (pass.use_bias) {
    // Apart: may approach until the gap closes; touching: pushed out softly, unless the point
    // is being caught (an impact: stopped rigidly, or a fast body would go on through).
    const Floats push_out = -softness.bias_rate * separation;
    const Floats push_max = splat<Floats>(pass.push_max_speed);
    const Floats soft_target =
        select_lanes(caught, zero, select_lanes(push_max < push_out, push_max, push_out));
    const Floats gap_target = -separation * splat<Floats>(pass.inverse_substep);
    target.target_speed =
        select_lanes(bouncing, velocity_bias, select_lanes(apart, gap_target, soft_target));
    const Masks rigid = bouncing | apart | caught;
    target.mass_scale = select_lanes(rigid, one, softness.mass_scale);
    target.impulse_scale = select_lanes(rigid, zero, softness.impulse_scale);
  } else {
    // Relaxing takes the push-out speed off touching points; points still apart keep theirs.
    target.active &= bouncing | ~apart;
    target.target_speed = select_lanes(bouncing, velocity_bias, zero);
    target.mass_scale = one;
    target.impulse_scale = zero;
  }
  return target;
}

// Point slot `slot`'s normal constraint on its own, in the lanes of `target.active` outside
// `skip` (lanes the pair solve already served).
template <int Lanes>
void solve_normal(BlockState<Lanes>& state, const NormalTarget<Lanes>& target,
                  BlockPointImpulse<Lanes>& point, const BlockPointSolve<Lanes>& solve,
                  typename LaneTypes<Lanes>::Masks skip) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  typedef typename LaneTypes<Lanes>::Masks Masks;
  const Floats zero = {};
  const Masks active = target.active & ~skip;
  const Floats anchor_ax = load_lanes<Floats>(point.anchor_ax);
  const Floats anchor_ay = load_lanes<Floats>(point.anchor_ay);
  const Floats anchor_bx = load_lanes<Floats>(point.anchor_bx);
  const Floats anchor_by = load_lanes<Floats>(point.anchor_by);
  const Floats normal_impulse = load_lanes<Floats>(point.normal_impulse);
  const Floats normal_speed = state.relative_speed(anchor_ax, anchor_ay, anchor_bx, anchor_by,
                                                   state.normal_x, state.normal_y);
  const Floats unclamped = normal_impulse -
                           load_lanes<Floats>(solve.normal_mass) * target.mass_scale *
                               (normal_speed - target.target_speed) -
                           target.impulse_scale * normal_impulse;
  const Floats accumulated = select_lanes(unclamped < zero, zero, unclamped);
  const Floats change = select_lanes(active, accumulated - normal_impulse, zero);
  store_lanes(point.normal_impulse, select_lanes(active, accumulated, normal_impulse));
  state.apply(anchor_ax, anchor_ay, anchor_bx, anchor_by, state.normal_x * change,
              state.normal_y * change);
}

// Both point slots' normal constraints at once where both take part (`block_point_pair`),
// through the inverse of their effective-mass matrix: the speeds the points must reach
// together (apart, bouncing, relaxing) are met with the coupling between the two solved
// exactly, while a soft point's spring push-out stays its own (weighed by its own effective
// mass, as solve_normal does, so a loaded contact yields as much as point by point: a pyramid
// sags no more). Where that would pull (a new impulse < 0), each point as if alone, from the
// same velocities. Both speeds are read before any impulse is applied and the two are applied
// as one (`apply_pair`), so the result does not depend on the points' order. Returns the lanes
// it served; the others are left to solve_normal point by point.
template <int Lanes>
typename LaneTypes<Lanes>::Masks solve_normal_pair(BlockState<Lanes>& state,
                                                   const NormalTarget<Lanes> (&target)[2],
                                                   BlockPointImpulse<Lanes> (&points)[2],
                                                   const ContactBlockSolve<Lanes>& solve) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  typedef typename LaneTypes<Lanes>::Masks Masks;
  const Floats zero = {};
  const Masks paired = flag_lanes(state.flags, block_point_pair) & target[0].active &
                       target[1].active;
  if (!any_lane(paired)) return paired;  // nothing to do: no lane changes
  Floats anchor_ax[2], anchor_ay[2], anchor_bx[2], anchor_by[2], impulse[2], error[2], push[2];
  for (int slot = 0; slot < 2; ++slot) {
    anchor_ax[slot] = load_lanes<Floats>(points[slot].anchor_ax);
    anchor_ay[slot] = load_lanes<Floats>(points[slot].anchor_ay);
    anchor_bx[slot] = load_lanes<Floats>(points[slot].anchor_bx);
    anchor_by[slot] = load_lanes<Floats>(points[slot].anchor_by);
    impulse[slot] = load_lanes<Floats>(points[slot].normal_impulse);
    // A soft point's target is a spring's push-out (each point's own, weighed by its own
    // effective mass as solve_normal does, so a loaded contact yields as much as it does point
    // by point); a rigid point's (apart, bouncing, relaxing) is a speed both points reach
    // together.
    const Masks soft = target[slot].impulse_scale != zero;
    const Floats kinematic = select_lanes(soft, zero, target[slot].target_speed);
    push[slot] = select_lanes(soft, load_lanes<Floats>(solve.points[slot].normal_mass) *
                                        target[slot].target_speed,
                              zero);
    error[slot] = state.relative_speed(anchor_ax[slot], anchor_ay[slot], anchor_bx[slot],
                                       anchor_by[slot], state.normal_x, state.normal_y) -
                  kinematic;
  }
  const Floats mass_00 = load_lanes<Floats>(solve.pair_mass_00);
  const Floats mass_01 = load_lanes<Floats>(solve.pair_mass_01);
  const Floats mass_11 = load_lanes<Floats>(solve.pair_mass_11);
  const Floats coupled[2] = {
      impulse[0] - target[0].mass_scale * (mass_00 * error[0] + mass_01 * error[1] - push[0]) -
          target[0].impulse_scale * impulse[0],
      impulse[1] - target[1].mass_scale * (mass_01 * error[0] + mass_11 * error[1] - push[1]) -
          target[1].impulse_scale * impulse[1]};
  const Masks both_push = (coupled[0] >= zero) & (coupled[1] >= zero);
  Floats change_x[2], change_y[2];
  for (int slot = 0; slot < 2; ++slot) {
    const Floats alone = impulse[slot] -
                         target[slot].mass_scale *
                             (load_lanes<Floats>(solve.points[slot].normal_mass) * error[slot] -
                              push[slot]) -
                         target[slot].impulse_scale * impulse[slot];
    const Floats clamped_alone = select_lanes(alone < zero, zero, alone);
    const Floats accumulated = select_lanes(both_push, coupled[slot], clamped_alone);
    const Floats change = select_lanes(paired, accumulated - impulse[slot], zero);
    store_lanes(points[slot].normal_impulse, select_lanes(paired, accumulated, impulse[slot]));
    change_x[slot] = state.normal_x * change;
    change_y[slot] = state.normal_y * change;
  }
  state.apply_pair(anchor_ax, anchor_ay, anchor_bx, anchor_by, change_x, change_y);
  return paired;
}

// A contact's friction: one constraint at the middle of its points. The two points of a 2D
// manifold lie on one face, so the tangent moves both alike (their tangential arms are equal):
// their friction is one constraint, whose Coulomb limit is the contact's, mu * (Pn0 + Pn1). A
// limit per point would let a contact slip before its total friction reached that cone when
// rotation loads its points unequally, and solving the points one after the other would make
// the result depend on their order. Anchored static friction in the biased pass (sticking
// contacts only; `drift`: the points' tangential drift (m) from where they stuck, averaged),
// Coulomb friction with the contact's current coefficient in the relax pass. The accumulated
// impulse is kept split evenly between the points (the same impulse at the middle).
template <int Lanes>
void solve_friction(BlockState<Lanes>& state, const SoftnessLanes<Lanes>& softness,
                    const typename LaneTypes<Lanes>::Floats (&drift)[2],
                    BlockPointImpulse<Lanes> (&points)[2], ContactBlockSolve<Lanes>& solve,
                    const WidePassSettings& pass) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  typedef typename LaneTypes<Lanes>::Masks Masks;
  const Floats zero = {};
  const Floats half = splat<Floats>(0.5f);
  const Masks present = flag_lanes(state.flags, block_point_present);
  const Masks two = flag_lanes(state.flags, block_point_present << 1);
  const Masks sliding = flag_lanes(state.flags, block_sliding);
  const Masks active = pass.use_bias ? present & ~sliding : present;

  Floats anchor_ax[2], anchor_ay[2], anchor_bx[2], anchor_by[2];
  for (int slot = 0; slot < 2; ++slot) {
    anchor_ax[slot] = load_lanes<Floats>(points[slot].anchor_ax);
    anchor_ay[slot] = load_lanes<Floats>(points[slot].anchor_ay);
    anchor_bx[slot] = load_lanes<Floats>(points[slot].anchor_bx);
    anchor_by[slot] = load_lanes<Floats>(points[slot].anchor_by);
  }
  const Floats middle_ax = select_lanes(two, half * (anchor_ax[0] + anchor_ax[1]), anchor_ax[0]);
  const Floats middle_ay = select_lanes(two, half * (anchor_ay[0] + anchor_ay[1]), anchor_ay[0]);
  const Floats middle_bx = select_lanes(two, half * (anchor_bx[0] + anchor_bx[1]), anchor_bx[0]);
  const Floats middle_by = select_lanes(two, half * (anchor_by[0] + anchor_by[1]), anchor_by[0]);
  const Floats tangent_impulse =
      load_lanes<Floats>(points[0].tangent_impulse) + load_lanes<Floats>(points[1].tangent_impulse);
  // Slot 0 holds the contact's tangent mass at the middle (see pack_contact).
  const Floats tangent_mass = load_lanes<Floats>(solve.points[0].tangent_mass);
  const Floats load =
      load_lanes<Floats>(points[0].normal_impulse) + load_lanes<Floats>(points[1].normal_impulse);
  const Floats tangent_speed = state.relative_speed(middle_ax, middle_ay, middle_bx, middle_by,
                                                    state.tangent_x, state.tangent_y);
  Floats unclamped, coefficient;
  if (pass.use_bias) {
    // Drive the points back to where they stuck, at the contact's stiffness.
    const Floats mean_drift = select_lanes(two, half * (drift[0] + drift[1]), drift[0]);
    const Floats push_max = splat<Floats>(pass.push_max_speed);
    const Floats target_speed =
        clamp_lanes(-softness.bias_rate * mean_drift, -push_max, push_max);
    unclamped = tangent_impulse - tangent_mass * (tangent_speed - target_speed);
    coefficient = load_lanes<Floats>(solve.static_friction);
  } else {
    unclamped = tangent_impulse - tangent_speed * tangent_mass;
    coefficient = select_lanes(sliding, load_lanes<Floats>(solve.dynamic_friction),
                               load_lanes<Floats>(solve.static_friction));
  }
  const Floats limit = coefficient * load;
  const Floats accumulated = clamp_lanes(unclamped, -limit, limit);
  if (!pass.use_bias) {
    // Both points' bits: the switch's "every point at the limit" reads the contact's cone.
    const Masks at_limit = present & (accumulated != unclamped) & (Masks{} + 3);
    store_lanes(solve.friction_at_limit, at_limit);
  }
  const Floats change = select_lanes(active, accumulated - tangent_impulse, zero);
  const Floats kept = select_lanes(active, accumulated, tangent_impulse);
  const Floats share = select_lanes(two, half * kept, kept);
  store_lanes(points[0].tangent_impulse, share);
  store_lanes(points[1].tangent_impulse, select_lanes(two, share, zero));
  state.apply(middle_ax, middle_ay, middle_bx, middle_by, state.tangent_x * change,
              state.tangent_y * change);
}

template <int Lanes>
void solve_blocks(const ContactBlockArrays<Lanes>& arrays, SolverBody* bodies,
                  const WidePassSettings& pass) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  const bool pulls_back = pass.use_bias && pass.friction;
  for (std::size_t i = 0; i < arrays.count; ++i) {
    ContactBlock<Lanes>& block = arrays.blocks[i];
    ContactBlockSolve<Lanes>& solve = arrays.solves[i];
    BlockState<Lanes> state(block, bodies);
    // The poses stay put through a velocity pass: every offset that reads them is taken first,
    // which frees their eight vector registers before the velocity work.
    Floats separation[2], drift[2] = {};
    for (int slot = 0; slot < 2; ++slot) {
      // Along the normal between the surface anchors (> 0: apart); along the tangent from
      // where the point last stuck (the sticking anchors are read by the biased pass only).
      const BlockPointSolve<Lanes>& point = solve.points[slot];
      separation[slot] = state.offset_along(point.surface_ax, point.surface_ay, point.surface_bx,
                                            point.surface_by, state.normal_x, state.normal_y) -
                         load_lanes<Floats>(point.rounding);
      if (!pulls_back) continue;
      const BlockPointStick<Lanes>& stick = arrays.sticks[i].points[slot];
      drift[slot] = state.offset_along(stick.stick_ax, stick.stick_ay, stick.stick_bx,
                                       stick.stick_by, state.tangent_x, state.tangent_y) -
                    load_lanes<Floats>(stick.stick_offset);
    }
    const SoftnessLanes<Lanes> softness(state, pass);
    const NormalTarget<Lanes> target[2] = {
        normal_target(state, softness, 0, separation[0], solve.points[0], pass),
        normal_target(state, softness, 1, separation[1], solve.points[1], pass)};
    const auto served = solve_normal_pair(state, target, block.points, solve);
    for (int slot = 0; slot < 2; ++slot) {
      // Where the pair solve served every lane the slot has, solving it alone changes nothing.
      if (!any_lane(target[slot].active & ~served)) continue;
      solve_normal(state, target[slot], block.points[slot], solve.points[slot], served);
    }
    if (pass.friction) solve_friction(state, softness, drift, block.points, solve, pass);
    state.store(block, bodies);
  }
}

template <int Lanes>
void warm_start_blocks(const ContactBlock<Lanes>* blocks, std::size_t count, SolverBody* bodies) {
  typedef typename LaneTypes<Lanes>::Floats Floats;
  for (std::size_t i = 0; i < count; ++i) {
    const ContactBlock<Lanes>& block = blocks[i];
    BlockState<Lanes> state(block, bodies);
    Floats anchor_ax[2], anchor_ay[2], anchor_bx[2], anchor_by[2], impulse_x[2], impulse_y[2];
    for (int slot = 0; slot < 2; ++slot) {
      const BlockPointImpulse<Lanes>& point = block.points[slot];
      const Floats normal_impulse = load_lanes<Floats>(point.normal_impulse);
      const Floats tangent_impulse = load_lanes<Floats>(point.tangent_impulse);
      anchor_ax[slot] = load_lanes<Floats>(point.anchor_ax);
      anchor_ay[slot] = load_lanes<Floats>(point.anchor_ay);
      anchor_bx[slot] = load_lanes<Floats>(point.anchor_bx);
      anchor_by[slot] = load_lanes<Floats>(point.anchor_by);
      impulse_x[slot] = state.normal_x * normal_impulse + state.tangent_x * tangent_impulse;
      impulse_y[slot] = state.normal_y * normal_impulse + state.tangent_y * tangent_impulse;
    }
    state.apply_pair(anchor_ax, anchor_ay, anchor_bx, anchor_by, impulse_x, impulse_y);
    state.store(block, bodies);
  }
}

}  // namespace
}  // namespace impulse2d

#pragma once
/// @file contact_block.h
/// Contacts laid out for the wide solver: `Lanes` contacts side by side, each field an array
/// of one value per lane (structure of arrays), so one vector instruction works on every lane.
/// The contacts of one block share no body the solve moves (see `contact_colouring.h`), which
/// makes the lanes independent: the result does not depend on how many lanes a block has.

#include "core/solver/softness.h"

#include <cstddef>
#include <cstdint>

namespace impulse2d {

/// Bits of `ContactBlock::flags`, one word per lane: what the contact is and, per point slot
/// `i` (0 or 1), `block_point_present << i` etc.
enum ContactBlockFlag : std::int32_t {
  block_moves_a = 1 << 0,         ///< the contacts move A (it has a finite mass)
  block_moves_b = 1 << 1,         ///< the contacts move B
  block_sliding = 1 << 2,         ///< the contact slides (dynamic friction)
  block_against_fixed = 1 << 3,   ///< one body never moves: the static softness applies
  block_point_present = 1 << 4,   ///< the lane's contact has point slot 0 (<< 1: slot 1)
  block_point_waiting = 1 << 6,   ///< point slot 0 sits this sub-step out (<< 1: slot 1)
  block_point_bouncing = 1 << 8,  ///< point slot 0 bounces in this sub-step (<< 1: slot 1)
  /// Both point slots are solved together through the inverse of their 2x2 effective-mass
  /// matrix (well conditioned), so a manifold pressed evenly (a box landing flat) gets even
  /// impulses whichever point comes first.
  block_point_pair = 1 << 10,
  /// Point slot 0 approached faster than a resting contact can (`ContactPoint::caught`): the
  /// biased pass stops it rigidly instead of softly (<< 1: slot 1).
  block_point_caught = 1 << 12,
};

// A block's lanes are split in three arrays by the passes that read them: the blocks are
// streamed a dozen times per step, so once they outgrow the cache their bytes are the solve's
// cost. Warm starting reads only the `ContactBlock` (84 bytes a lane), the relax pass that and
// the `ContactBlockSolve` (172), the biased pass all three (212).

/// What warm starting applies at one manifold point slot, one value per lane.
template <int Lanes>
struct BlockPointImpulse {
  float anchor_ax[Lanes];        ///< point relative to A's centre, world axes, metres
  float anchor_ay[Lanes];        ///< (y)
  float anchor_bx[Lanes];        ///< point relative to B's centre, world axes, metres
  float anchor_by[Lanes];        ///< (y)
  float normal_impulse[Lanes];   ///< accumulated normal impulse, N s
  float tangent_impulse[Lanes];  ///< accumulated friction impulse, N s
};

/// `Lanes` contacts as every pass reads them (structure of arrays). An unused lane has no
/// points and moves nothing.
template <int Lanes>
struct alignas(4 * Lanes) ContactBlock {
  std::int32_t body_a[Lanes];         ///< A's body slot (0 in an unused lane)
  std::int32_t body_b[Lanes];         ///< B's body slot (0 in an unused lane)
  std::int32_t flags[Lanes];          ///< `ContactBlockFlag` bits
  float normal_x[Lanes];              ///< unit normal from A to B
  float normal_y[Lanes];              ///< (y)
  float inverse_mass_a[Lanes];        ///< 1/kg
  float inverse_mass_b[Lanes];        ///< 1/kg
  float inverse_inertia_a[Lanes];     ///< 1/(kg m^2)
  float inverse_inertia_b[Lanes];     ///< 1/(kg m^2)
  BlockPointImpulse<Lanes> points[2];  ///< manifold point slots
};

/// What both solve passes read at one manifold point slot besides its impulses.
template <int Lanes>
struct BlockPointSolve {
  float surface_ax[Lanes];     ///< A's core point in A's frame, metres
  float surface_ay[Lanes];     ///< (y)
  float surface_bx[Lanes];     ///< B's core point in B's frame, metres
  float surface_by[Lanes];     ///< (y)
  float rounding[Lanes];       ///< the two shapes' roundings (m): separation = offset - this
  float normal_mass[Lanes];    ///< effective mass along the normal, kg (0: no point)
  float tangent_mass[Lanes];   ///< effective mass along the tangent, kg (0: no point)
  float velocity_bias[Lanes];  ///< target normal speed of a bouncing point, m/s
};

/// The same block's lanes as both solve passes read them besides its `ContactBlock`.
template <int Lanes>
struct alignas(4 * Lanes) ContactBlockSolve {
  /// Bit i set where the last relax pass clamped point slot i's friction at the Coulomb limit.
  std::int32_t friction_at_limit[Lanes];
  float static_friction[Lanes];       ///< mixed coefficient
  float dynamic_friction[Lanes];      ///< mixed coefficient
  /// Inverse of the two points' 2x2 normal effective-mass matrix (kg), where
  /// `block_point_pair` is set: entry (0,0), (0,1) = (1,0) and (1,1).
  float pair_mass_00[Lanes];
  float pair_mass_01[Lanes];  ///< (0,1) and (1,0), kg
  float pair_mass_11[Lanes];  ///< (1,1), kg
  BlockPointSolve<Lanes> points[2];   ///< manifold point slots
};

/// Where one manifold point slot last stuck, one value per lane (static friction's anchor).
template <int Lanes>
struct BlockPointStick {
  float stick_ax[Lanes];      ///< where the point last stuck, in A's frame, metres
  float stick_ay[Lanes];      ///< (y)
  float stick_bx[Lanes];      ///< the same point in B's frame, metres
  float stick_by[Lanes];      ///< (y)
  float stick_offset[Lanes];  ///< tangential offset (m) of the two when it stuck
};

/// The same block's sticking anchors, read by the biased pass only.
template <int Lanes>
struct alignas(4 * Lanes) ContactBlockStick {
  BlockPointStick<Lanes> points[2];  ///< manifold point slots
};

/// The three parts of a run of blocks, index for index.
template <int Lanes>
struct ContactBlockArrays {
  ContactBlock<Lanes>* blocks = nullptr;       ///< read by every pass
  ContactBlockSolve<Lanes>* solves = nullptr;  ///< read by both solve passes
  const ContactBlockStick<Lanes>* sticks = nullptr;  ///< read by the biased pass
  std::size_t count = 0;                       ///< blocks in each array
};

/// What one pass of the wide solver needs besides the blocks and bodies.
struct WidePassSettings {
  float inverse_substep = 0.0f;  ///< 1/s: one over the sub-step
  /// Softness of contacts against a body they never move (`block_against_fixed`).
  Softness static_softness;
  Softness dynamic_softness;  ///< softness of contacts between two moving bodies
  float push_max_speed = 0.0f;   ///< m/s: fastest soft push-out
  bool use_bias = true;          ///< true: the soft (biased) pass; false: the relax pass
  bool friction = true;          ///< friction on
};

}  // namespace impulse2d

#pragma once
/// @file contact_block.h
/// Contacts laid out for the wide solver: `Lanes` contacts side by side, each field an array
/// of one value per lane (structure of arrays), so one vector instruction works on every lane.
/// The contacts of one block share no body the solve moves (see `contact_colouring.h`), which
/// makes the lanes independent: the result does not depend on how many lanes a block has.

#include <cstdint>

namespace impulse2d {

/// The solver's data of one manifold point slot, one value per lane.
template <int Lanes>
struct BlockPoint {
  float anchor_ax[Lanes];        ///< point relative to A's centre, world axes, metres
  float anchor_ay[Lanes];        ///< (y)
  float anchor_bx[Lanes];        ///< point relative to B's centre, world axes, metres
  float anchor_by[Lanes];        ///< (y)
  float surface_ax[Lanes];       ///< A's surface point in A's frame, metres
  float surface_ay[Lanes];       ///< (y)
  float surface_bx[Lanes];       ///< B's surface point in B's frame, metres
  float surface_by[Lanes];       ///< (y)
  float stick_ax[Lanes];         ///< where the point last stuck, in A's frame, metres
  float stick_ay[Lanes];         ///< (y)
  float stick_bx[Lanes];         ///< the same point in B's frame, metres
  float stick_by[Lanes];         ///< (y)
  float stick_offset[Lanes];     ///< tangential offset (m) of the two when it stuck
  float normal_mass[Lanes];      ///< effective mass along the normal, kg (0: no point)
  float tangent_mass[Lanes];     ///< effective mass along the tangent, kg (0: no point)
  float normal_impulse[Lanes];   ///< accumulated normal impulse, N s
  float tangent_impulse[Lanes];  ///< accumulated friction impulse, N s
  float velocity_bias[Lanes];    ///< target normal speed of a bouncing point, m/s
  std::int32_t present[Lanes];   ///< -1 where the lane's contact has this point, else 0
  std::int32_t waiting[Lanes];   ///< -1 where the point sits this sub-step out
  std::int32_t bouncing[Lanes];  ///< -1 where the point bounces in this sub-step
  /// -1 where the last relax pass clamped the friction at the Coulomb limit.
  std::int32_t friction_at_limit[Lanes];
};

/// `Lanes` contacts, structure of arrays. An unused lane has no points and moves nothing.
template <int Lanes>
struct alignas(4 * Lanes) ContactBlock {
  std::int32_t body_a[Lanes];         ///< A's body slot (0 in an unused lane)
  std::int32_t body_b[Lanes];         ///< B's body slot (0 in an unused lane)
  std::int32_t moves_a[Lanes];        ///< nonzero where contacts move A (it has a finite mass)
  std::int32_t moves_b[Lanes];        ///< nonzero where contacts move B
  std::int32_t contact_index[Lanes];  ///< index in the world's contact list, -1 unused
  std::int32_t sliding[Lanes];        ///< -1 where the contact slides (dynamic friction)
  float normal_x[Lanes];              ///< unit normal from A to B
  float normal_y[Lanes];              ///< (y)
  float inverse_mass_a[Lanes];        ///< 1/kg
  float inverse_mass_b[Lanes];        ///< 1/kg
  float inverse_inertia_a[Lanes];     ///< 1/(kg m^2)
  float inverse_inertia_b[Lanes];     ///< 1/(kg m^2)
  float static_friction[Lanes];       ///< mixed coefficient
  float dynamic_friction[Lanes];      ///< mixed coefficient
  float bias_rate[Lanes];             ///< 1/s: soft push-out speed per metre of overlap
  float mass_scale[Lanes];            ///< soft constraint: fraction of the rigid impulse
  float impulse_scale[Lanes];         ///< soft constraint: accumulated impulse relaxed per pass
  BlockPoint<Lanes> points[2];        ///< manifold point slots
};

/// What one pass of the wide solver needs besides the blocks and bodies.
struct WidePassSettings {
  float inverse_substep = 0.0f;  ///< 1/s: one over the sub-step
  float push_max_speed = 0.0f;   ///< m/s: fastest soft push-out
  bool use_bias = true;          ///< true: the soft (biased) pass; false: the relax pass
  bool friction = true;          ///< friction on
};

}  // namespace impulse2d

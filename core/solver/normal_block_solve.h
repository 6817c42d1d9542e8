#pragma once
/// @file normal_block_solve.h
/// Both normal impulses of a two-point manifold solved at once (Box2D v2's block solver):
/// the 2x2 linear complementarity problem of the pair's effective-mass matrix.

#include "core/solver/body_state.h"
#include "core/contact.h"

namespace impulse2d {

/// Finds accumulated normal impulses x >= 0 for the two points of `contact` with
/// v = K x + b >= 0 and x . v = 0, where K is the 2x2 effective-mass matrix of `mass` (1/kg)
/// and b the points' normal velocities less their `velocity_bias` targets without the
/// accumulated impulses, by trying the four cases in turn; applies the change to `a` and `b`
/// through `mass`. Returns false, changing nothing, when K is ill-conditioned or no case
/// holds (the caller then solves point by point). `mass` may differ from `contact.mass`
/// (the shock pass treats the supporting body as fixed).
bool solve_normal_block(Body& a, Body& b, Contact& contact, const PairMass& mass);

}  // namespace impulse2d

#pragma once
/// @file position_correction.h
/// Removes overlap the velocity solve left behind, by moving bodies directly.

#include "core/solver/body_state.h"
#include "core/contact.h"
#include "core/settings.h"

#include <vector>

namespace impulse2d {

/// The tutorial's linear projection, once per step: each contact moves its bodies apart along
/// the normal by percent * max(depth - slop, 0), split by inverse mass. Depth is the deepest
/// point of the manifold as detected this step. No rotation.
void correct_positions_linear(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                              const WorldSettings& settings);

/// Nonlinear Gauss-Seidel: `position_iterations` passes; each point's separation is
/// recomputed from the bodies' current transforms (anchors fixed in each body), and a
/// position-level impulse percent * (separation + slop), clamped to max_correction, moves and
/// turns both bodies. Returns the largest overlap (metres) seen in the last pass.
float correct_positions_nonlinear(const std::vector<Contact>& contacts, std::vector<Body>& bodies,
                                  const WorldSettings& settings);

}  // namespace impulse2d

#pragma once
/// @file solver_body.h
/// The hot state of one body slot as the wide contact solver reads and writes it: velocity and
/// pose in 32 bytes, so a contact's two bodies cost two cache lines instead of the ~10 a full
/// `Body` spans. Plain floats (no GLM) so the vector kernels compiled for other instruction
/// sets share it without inline functions.

#include <cstdint>

namespace impulse2d {

/// One body slot's velocity and pose for the contact solve.
struct alignas(32) SolverBody {
  float velocity_x = 0.0f;        ///< m/s
  float velocity_y = 0.0f;        ///< m/s
  float angular_velocity = 0.0f;  ///< rad/s, counter-clockwise
  float angle = 0.0f;             ///< radians, unwrapped (the body's `angle`)
  float position_x = 0.0f;        ///< centre of mass, metres
  float position_y = 0.0f;        ///< centre of mass, metres
  float cosine = 1.0f;            ///< cos of the body's angle
  float sine = 0.0f;              ///< sin of the body's angle
};

static_assert(sizeof(SolverBody) == 32, "SolverBody is meant to fill half a cache line");

}  // namespace impulse2d

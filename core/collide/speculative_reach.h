#pragma once
/// @file speculative_reach.h
/// How far a body can move in the coming step, so speculative contacts cover it.

#include "core/solver/body_state.h"
#include "core/settings.h"
#include "core/solver/worker_pool.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// Farthest distance (m) from the centre of mass of the points a turn sweeps: a polygon's
/// farthest vertex (its rounding turns in place about each vertex), a capsule's farthest
/// cap centre, a segment's farthest end; 0 for a circle (turning about its centre moves no
/// surface point) and for a box (never rotates).
float rotation_reach(const Shape& shape);

/// For each living slot, the distance (metres) any point of the body can travel in the next
/// `dt` seconds: (|v| + |g| gravity_scale dt) dt for the centre plus |w| dt times the
/// `rotation_reach` for a rotating shape. Zero for static bodies
/// and sleeping ones, and everywhere when `settings.speculative_margin` is 0. With a `pool`,
/// the bodies are shared among its workers (each is its own work).
void compute_speculative_reach(const std::vector<Body>& bodies,
                               const std::vector<std::uint8_t>& alive,
                               const WorldSettings& settings, float dt,
                               std::vector<float>& reach, WorkerPool* pool = nullptr);

/// Each living slot's AABB grown by `margin / 2 + reach` (metres) on every side, so two bodies
/// closer than `margin` plus their two reaches have overlapping bounds (with a `pool`, shared
/// among its workers).
void compute_speculative_bounds(const std::vector<Body>& bodies,
                                const std::vector<std::uint8_t>& alive,
                                const std::vector<float>& reach, float margin,
                                std::vector<Aabb>& bounds, WorkerPool* pool = nullptr);

}  // namespace impulse2d

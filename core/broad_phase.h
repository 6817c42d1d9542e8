#pragma once
/// @file broad_phase.h
/// Finds candidate pairs of bodies whose bounding boxes overlap.

#include "core/body.h"
#include "core/settings.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace impulse2d {

/// A candidate pair of body slots, first < second.
using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// True when two bodies may collide at all: at least one is awake and not static, and their
/// collision layers share a bit.
bool bodies_can_collide(const Body& a, const Body& b);

/// Broad phase with reusable scratch buffers (no allocation once warmed up).
class BroadPhase {
 public:
  /// Fills `pairs` with every pair of living slots whose `bounds` (one box per slot) overlap
  /// and that
  /// `bodies_can_collide`, each once as (smaller slot, larger slot), sorted ascending.
  /// `method` picks brute force (O(n^2)) or sort-and-sweep on the x axis (O(n log n + k)).
  void find_pairs(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                  const std::vector<Aabb>& bounds, BroadPhaseMethod method,
                  std::vector<BodyPair>& pairs);

 private:
  /// A living slot's bounds, copied so that the sweep reads one contiguous array.
  struct SweepEntry {
    Aabb bounds;         ///< the slot's box, metres
    std::uint32_t slot;  ///< body slot
  };
  std::vector<SweepEntry> sorted_;  // living slots ordered by (bounds.lower.x, slot)
};

}  // namespace impulse2d

#pragma once
/// @file sleep.h
/// Puts islands of touching bodies to sleep when all of them have been slow for a while, and
/// wakes a whole island when any member is disturbed.

#include "core/solver/body_state.h"
#include "core/contact.h"
#include "core/solver/joint_solver.h"
#include "core/settings.h"
#include "core/solver/worker_pool.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// Island bookkeeping with reusable buffers.
class SleepIslands {
 public:
  /// Advances each awake dynamic body's slow-time by `dt`, builds islands from the enabled
  /// contacts and the living joints (static bodies do not join islands; a moving kinematic body keeps what touches it
  /// awake), then sends to sleep every island whose members have all been slow for
  /// `settings.time_to_sleep` and wakes every island that has a sleeping and a fast member.
  /// With a `pool`, the passes over the bodies are shared among its workers (each body is its
  /// own work; the joining of islands and the per-island minimum stay on this thread): the
  /// same islands and the same bits for any worker count.
  void update(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
              const std::vector<Contact>& contacts, const std::vector<Joint>& joints,
              const std::vector<std::uint8_t>& joint_alive, const WorldSettings& settings, float dt,
              WorkerPool* pool = nullptr);

 private:
  std::uint32_t find_root(std::uint32_t slot);
  std::vector<std::uint32_t> parent_;    // union-find forest over slots
  std::vector<std::uint32_t> root_;      // per slot: its island's root, once the islands are joined
  std::vector<float> island_min_slow_;   // per root: least slow-time of the members, seconds
};

}  // namespace impulse2d

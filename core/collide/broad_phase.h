#pragma once
/// @file broad_phase.h
/// Finds candidate pairs of bodies whose bounding boxes overlap, and keeps the dynamic trees
/// that world queries and bullet sweeps search.

#include "core/solver/body_state.h"
#include "core/collide/dynamic_tree.h"
#include "core/settings.h"
#include "core/solver/worker_pool.h"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace impulse2d {

/// A candidate pair of body slots, first < second.
using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// True when two bodies may collide at all: at least one is awake and not static, and their
/// collision layers share a bit.
bool bodies_can_collide(const Body& a, const Body& b);

/// Broad phase with reusable buffers (no allocation once warmed up). Every living body has a
/// proxy: a fat box (its bounds grown by `fat_margin`) in the tree of its body type, moved only
/// when the bounds it must cover stick out of it. With `BroadPhaseMethod::DynamicTree` the
/// pairs of overlapping fat boxes persist from step to step and only moved proxies are queried
/// again; the pairs handed on are still exactly those of the other methods.
class BroadPhase {
 public:
  /// How far (metres) a proxy's fat box reaches beyond the bounds it covers (Box2D's 0.1 m).
  static constexpr float fat_margin = 0.1f;

  /// Gives the new body in `slot`, of type `type`, a proxy covering `bounds` (metres).
  void add_body(std::uint32_t slot, BodyType type, const Aabb& bounds);
  /// Removes the proxy of the body in `slot`.
  void remove_body(std::uint32_t slot);
  /// Makes the proxy of `slot` cover `bounds` (metres): when they stick out of its fat box,
  /// it gets `bounds` grown by `fat_margin` and is queued to look for new pairs. Non-finite
  /// bounds take the slot out of the trees; it is then a candidate of every query.
  void cover(std::uint32_t slot, const Aabb& bounds);

  /// Fills `pairs` with every pair of living slots whose `bounds` (one box per slot, metres)
  /// overlap and that `bodies_can_collide`, each once as (smaller slot, larger slot), sorted
  /// ascending. `method` picks brute force (O(n^2)), sort-and-sweep on the x axis
  /// (O(n log n + k)) or the persistent tree pairs (O(n + pairs + moved log n); first covers
  /// every living slot's `bounds`). With a `pool`, the tree pairing's queries of the moved
  /// proxies are shared among its workers (the trees are only read; the finds are merged in a
  /// fixed order and sorted): the same pairs for any worker count.
  void find_pairs(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                  const std::vector<Aabb>& bounds, BroadPhaseMethod method,
                  std::vector<BodyPair>& pairs, WorkerPool* pool = nullptr);

  /// Replaces `slots` with the slots, ascending, whose fat boxes overlap or touch `box`
  /// (metres): a superset of the bodies whose covered bounds overlap it.
  void query(const Aabb& box, std::vector<std::uint32_t>& slots) const;
  /// Replaces `slots` with the slots, ascending, whose fat boxes the segment `origin` ->
  /// `origin + translation` (metres) meets: a superset of the bodies the segment can hit.
  void raycast(vec2 origin, vec2 translation, std::vector<std::uint32_t>& slots) const;

  /// Calls `visit(slot)` for each slot whose fat box overlaps or touches `box` (and each slot
  /// with non-finite bounds), in tree order, allocating nothing; stops when `visit` returns
  /// false. Callers that need slot order sort or select themselves (world queries).
  template <typename Visit>
  void visit_overlaps(const Aabb& box, Visit&& visit) const {
    for (const std::uint32_t slot : unbounded_) {
      if (!visit(slot)) return;
    }
    bool going = true;
    for (const DynamicTree& tree : trees_) {
      tree.query(box, [&](std::uint32_t slot) { return going = visit(slot); });
      if (!going) return;
    }
  }
  /// The tree holding the proxies of bodies of `type` (for tests and statistics).
  const DynamicTree& tree(BodyType type) const { return trees_[static_cast<std::size_t>(type)]; }

 private:
  /// A slot's place in the trees.
  struct Proxy {
    std::int32_t node = DynamicTree::null_node;  ///< leaf in trees_[type]; null when out
    BodyType type = BodyType::Static;            ///< which tree
    bool unbounded = false;  ///< bounds were not finite: in `unbounded_`, not in a tree
    bool moved = false;      ///< queued in `moved_`
    /// `pairing_epoch_` when the proxy last changed (made, moved, removed): a kept pair of two
    /// proxies that did not change since the last pairing still overlaps.
    std::uint32_t changed_epoch = 0;
  };
  /// What `bodies_can_collide` reads of a body, copied once a step in slot order so that the
  /// pair loop reads 8 bytes per slot instead of three cache lines of a `Body` (issue 33).
  struct PairFilter {
    std::uint32_t collision_layers = 0;  ///< the body's layers
    BodyType type = BodyType::Static;    ///< the body's type
    bool moving = false;                 ///< awake and not static
    bool sensor = false;                 ///< a sensor: pairs with nothing
  };
  /// A living slot's bounds, copied so that the sweep reads one contiguous array.
  struct SweepEntry {
    Aabb bounds;         ///< the slot's box, metres
    std::uint32_t slot;  ///< body slot
  };

  void mark_moved(std::uint32_t slot);
  void mark_changed(std::uint32_t slot) { proxies_[slot].changed_epoch = pairing_epoch_; }
  void leave_unbounded(std::uint32_t slot);
  void find_tree_pairs(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                       const std::vector<Aabb>& bounds, std::vector<BodyPair>& pairs,
                       WorkerPool* pool);
  // Appends to `into` every pair of moved proxy `slot` with another proxy whose fat box
  // overlaps its own (reads the trees only).
  void query_moved(std::uint32_t slot, std::vector<BodyPair>& into) const;
  bool fat_boxes_overlap(const BodyPair& pair) const;
  bool filters_can_collide(const BodyPair& pair) const;

  std::array<DynamicTree, 3> trees_;        // indexed by BodyType
  std::vector<Proxy> proxies_;              // per slot
  std::vector<std::uint32_t> moved_;        // slots whose fat box changed since the last pairing
  std::vector<std::uint32_t> unbounded_;    // slots with non-finite bounds
  std::vector<BodyPair> tree_pairs_;        // overlapping fat boxes, sorted (DynamicTree)
  std::vector<BodyPair> found_;             // new pairs of moved proxies (reused)
  std::vector<std::vector<BodyPair>> found_parts_;  // found_ by part of moved_ (reused)
  std::vector<BodyPair> merged_;            // next tree_pairs_ (reused)
  std::vector<SweepEntry> sorted_;          // living slots ordered by (bounds.lower.x, slot)
  std::vector<PairFilter> filters_;         // per slot, refreshed by each tree pairing
  std::uint32_t pairing_epoch_ = 0;         // tree pairings done (wraps; see Proxy)
};

}  // namespace impulse2d

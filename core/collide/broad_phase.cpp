#include "core/collide/broad_phase.h"

#include <algorithm>

namespace impulse2d {

namespace {

bool is_moving(const Body& body) { return body.type != BodyType::Static && body.awake; }

// Only pairs with a dynamic body can collide (see `bodies_can_collide`): static proxies are
// never tested against static or kinematic ones.
bool types_can_pair(BodyType a, BodyType b) {
  return a == BodyType::Dynamic || b == BodyType::Dynamic;
}

bool is_finite_box(const Aabb& box) { return is_finite(box.lower) && is_finite(box.upper); }

bool contains(const Aabb& outer, const Aabb& inner) {
  return outer.lower.x <= inner.lower.x && outer.lower.y <= inner.lower.y &&
         outer.upper.x >= inner.upper.x && outer.upper.y >= inner.upper.y;
}

Aabb fatten(const Aabb& box) {
  const vec2 grow(BroadPhase::fat_margin);
  return Aabb{box.lower - grow, box.upper + grow};
}

BodyPair ordered(std::uint32_t a, std::uint32_t b) { return a < b ? BodyPair{a, b} : BodyPair{b, a}; }

}  // namespace

bool bodies_can_collide(const Body& a, const Body& b) {
  if (!is_moving(a) && !is_moving(b)) return false;
  if (a.type != BodyType::Dynamic && b.type != BodyType::Dynamic) return false;
  if (a.is_sensor || b.is_sensor) return false;  // sensors only report overlaps (events)
  return (a.collision_layers & b.collision_layers) != 0;
}

void BroadPhase::find_pairs(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                            const std::vector<Aabb>& bounds, BroadPhaseMethod method,
                            std::vector<BodyPair>& pairs, WorkerPool* pool) {
  pairs.clear();
  if (method == BroadPhaseMethod::DynamicTree) {
    find_tree_pairs(bodies, alive, bounds, pairs, pool);
    return;
  }
  const auto slot_count = static_cast<std::uint32_t>(bodies.size());
  if (method == BroadPhaseMethod::BruteForce) {
    for (std::uint32_t i = 0; i < slot_count; ++i) {
      if (!alive[i]) continue;
      for (std::uint32_t j = i + 1; j < slot_count; ++j) {
        if (!alive[j]) continue;
        if (bounds[i].overlaps(bounds[j]) && bodies_can_collide(bodies[i], bodies[j])) {
          pairs.emplace_back(i, j);
        }
      }
    }
    return;
  }

  sorted_.clear();
  for (std::uint32_t i = 0; i < slot_count; ++i) {
    if (alive[i]) sorted_.push_back({bounds[i], i});
  }
  // Ties on lower.x are broken by slot so the order never depends on the sort's internals.
  std::sort(sorted_.begin(), sorted_.end(), [](const SweepEntry& a, const SweepEntry& b) {
    return a.bounds.lower.x < b.bounds.lower.x ||
           (a.bounds.lower.x == b.bounds.lower.x && a.slot < b.slot);
  });
  const std::size_t count = sorted_.size();
  for (std::size_t i = 0; i < count; ++i) {
    const SweepEntry& first = sorted_[i];
    for (std::size_t j = i + 1; j < count; ++j) {
      const SweepEntry& second = sorted_[j];
      if (second.bounds.lower.x > first.bounds.upper.x) break;
      if (first.bounds.overlaps(second.bounds) &&
          bodies_can_collide(bodies[first.slot], bodies[second.slot])) {
        pairs.emplace_back(std::min(first.slot, second.slot), std::max(first.slot, second.slot));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

void BroadPhase::mark_moved(std::uint32_t slot) {
  if (proxies_[slot].moved) return;
  proxies_[slot].moved = true;
  moved_.push_back(slot);
}

void BroadPhase::leave_unbounded(std::uint32_t slot) {
  if (!proxies_[slot].unbounded) return;
  proxies_[slot].unbounded = false;
  unbounded_.erase(std::find(unbounded_.begin(), unbounded_.end(), slot));
}

void BroadPhase::add_body(std::uint32_t slot, BodyType type, const Aabb& bounds) {
  if (proxies_.size() <= slot) proxies_.resize(slot + 1);
  const bool queued = proxies_[slot].moved;  // a removed body's slot may still be queued
  proxies_[slot] = Proxy{};
  proxies_[slot].type = type;
  proxies_[slot].moved = queued;
  mark_changed(slot);
  cover(slot, bounds);
}

void BroadPhase::remove_body(std::uint32_t slot) {
  Proxy& proxy = proxies_[slot];
  if (proxy.node != DynamicTree::null_node) {
    trees_[static_cast<std::size_t>(proxy.type)].destroy_proxy(proxy.node);
    proxy.node = DynamicTree::null_node;
  }
  mark_changed(slot);
  leave_unbounded(slot);
}

void BroadPhase::cover(std::uint32_t slot, const Aabb& bounds) {
  Proxy& proxy = proxies_[slot];
  DynamicTree& tree = trees_[static_cast<std::size_t>(proxy.type)];
  // The common case first: bounds still inside the (finite) fat box are finite themselves.
  if (proxy.node != DynamicTree::null_node && contains(tree.box(proxy.node), bounds)) return;
  mark_changed(slot);
  if (!is_finite_box(bounds)) {
    if (proxy.node != DynamicTree::null_node) tree.destroy_proxy(proxy.node);
    proxy.node = DynamicTree::null_node;
    if (!proxy.unbounded) {
      proxy.unbounded = true;
      unbounded_.push_back(slot);
    }
    return;
  }
  if (proxy.node == DynamicTree::null_node) {
    leave_unbounded(slot);
    proxy.node = tree.create_proxy(fatten(bounds), slot);
  } else {
    tree.move_proxy(proxy.node, fatten(bounds));
  }
  mark_moved(slot);
}

inline bool BroadPhase::fat_boxes_overlap(const BodyPair& pair) const {
  const Proxy& first = proxies_[pair.first];
  const Proxy& second = proxies_[pair.second];
  if (first.node == DynamicTree::null_node || second.node == DynamicTree::null_node) return false;
  if (!types_can_pair(first.type, second.type)) return false;
  return trees_[static_cast<std::size_t>(first.type)].box(first.node).overlaps(
      trees_[static_cast<std::size_t>(second.type)].box(second.node));
}

// `bodies_can_collide` of the pair's bodies, read from their filters.
inline bool BroadPhase::filters_can_collide(const BodyPair& pair) const {
  const PairFilter& a = filters_[pair.first];
  const PairFilter& b = filters_[pair.second];
  if (!a.moving && !b.moving) return false;
  if (a.type != BodyType::Dynamic && b.type != BodyType::Dynamic) return false;
  if (a.sensor || b.sensor) return false;
  return (a.collision_layers & b.collision_layers) != 0;
}

// Moved proxies per part of the tree pairing's queries (a query is a few hundred nanoseconds).
constexpr std::size_t moved_per_part = 64;

void BroadPhase::query_moved(std::uint32_t slot, std::vector<BodyPair>& into) const {
  const Proxy& proxy = proxies_[slot];
  if (proxy.node == DynamicTree::null_node) return;
  const Aabb fat = trees_[static_cast<std::size_t>(proxy.type)].box(proxy.node);
  for (std::size_t type = 0; type < trees_.size(); ++type) {
    if (!types_can_pair(proxy.type, static_cast<BodyType>(type))) continue;
    trees_[type].query(fat, [&](std::uint32_t other) {
      if (other != slot) into.push_back(ordered(slot, other));
      return true;
    });
  }
}

// The persistent pairs are every pair of proxies whose fat boxes overlap, except pairs of a
// proxy still queued in `moved_`. Each call first lets every living slot's proxy cover its
// bounds, queries the trees with each moved proxy's fat box, merges what it found into the
// sorted pairs while dropping pairs whose fat boxes came apart, and hands on the pairs whose
// exact bounds overlap. A fat box contains its slot's bounds, so no overlapping pair is missed.
void BroadPhase::find_tree_pairs(const std::vector<Body>& bodies,
                                 const std::vector<std::uint8_t>& alive,
                                 const std::vector<Aabb>& bounds, std::vector<BodyPair>& pairs,
                                 WorkerPool* pool) {
  const auto slot_count = static_cast<std::uint32_t>(bodies.size());
  // One pass in slot order: each proxy covers its bounds and each slot's filter is copied, so
  // that the pair loop below touches no `Body` (at 100k bodies its reads of three cache lines
  // per body missed the cache; issue 33).
  if (filters_.size() < slot_count) filters_.resize(slot_count);
  for (std::uint32_t i = 0; i < slot_count; ++i) {
    if (!alive[i]) continue;
    cover(i, bounds[i]);
    const Body& body = bodies[i];
    filters_[i] = PairFilter{body.collision_layers, body.type, is_moving(body), body.is_sensor};
  }

  // The moved proxies' queries, in parts of `moved_` that the workers share; each part's finds
  // go to its own list, and the lists are joined in order (then sorted).
  for (const std::uint32_t slot : moved_) proxies_[slot].moved = false;
  const std::size_t parts = (moved_.size() + moved_per_part - 1) / moved_per_part;
  if (found_parts_.size() < parts) found_parts_.resize(parts);
  parallel_for(pool, parts, 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part) {
      std::vector<BodyPair>& found = found_parts_[part];
      found.clear();
      const std::size_t last = std::min(moved_.size(), (part + 1) * moved_per_part);
      for (std::size_t i = part * moved_per_part; i < last; ++i) query_moved(moved_[i], found);
    }
  });
  found_.clear();
  for (std::size_t part = 0; part < parts; ++part) {
    found_.insert(found_.end(), found_parts_[part].begin(), found_parts_[part].end());
  }
  moved_.clear();
  std::sort(found_.begin(), found_.end());
  found_.erase(std::unique(found_.begin(), found_.end()), found_.end());

  // Merge the two sorted lists, keeping pairs whose fat boxes still overlap.
  merged_.clear();
  std::size_t kept = 0;
  std::size_t fresh = 0;
  while (kept < tree_pairs_.size() || fresh < found_.size()) {
    BodyPair pair;
    bool unchanged = false;  // a kept pair whose proxies did not change: its fat boxes overlap
    if (fresh == found_.size() || (kept < tree_pairs_.size() && tree_pairs_[kept] < found_[fresh])) {
      pair = tree_pairs_[kept++];
      unchanged = proxies_[pair.first].changed_epoch != pairing_epoch_ &&
                  proxies_[pair.second].changed_epoch != pairing_epoch_;
    } else {
      pair = found_[fresh++];
      if (kept < tree_pairs_.size() && tree_pairs_[kept] == pair) ++kept;
    }
    if (!unchanged && !fat_boxes_overlap(pair)) continue;
    merged_.push_back(pair);
    if (bounds[pair.first].overlaps(bounds[pair.second]) && filters_can_collide(pair)) {
      pairs.push_back(pair);
    }
  }
  std::swap(tree_pairs_, merged_);
  ++pairing_epoch_;

  // Slots whose bounds are not finite are in no tree: test them against every living slot
  // exactly as brute force does.
  if (unbounded_.empty()) return;
  for (const std::uint32_t slot : unbounded_) {
    for (std::uint32_t other = 0; other < slot_count; ++other) {
      if (other == slot || !alive[other]) continue;
      const BodyPair pair = ordered(slot, other);
      if (bounds[pair.first].overlaps(bounds[pair.second]) &&
          bodies_can_collide(bodies[pair.first], bodies[pair.second])) {
        pairs.push_back(pair);
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

void BroadPhase::query(const Aabb& box, std::vector<std::uint32_t>& slots) const {
  slots.assign(unbounded_.begin(), unbounded_.end());
  for (const DynamicTree& tree : trees_) {
    tree.query(box, [&slots](std::uint32_t slot) {
      slots.push_back(slot);
      return true;
    });
  }
  std::sort(slots.begin(), slots.end());
}

void BroadPhase::raycast(vec2 origin, vec2 translation, std::vector<std::uint32_t>& slots) const {
  slots.assign(unbounded_.begin(), unbounded_.end());
  for (const DynamicTree& tree : trees_) {
    tree.raycast(origin, translation, [&slots](std::uint32_t slot) {
      slots.push_back(slot);
      return true;
    });
  }
  std::sort(slots.begin(), slots.end());
}

}  // namespace impulse2d

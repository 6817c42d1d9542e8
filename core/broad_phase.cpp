#include "core/broad_phase.h"

#include <algorithm>

namespace impulse2d {

namespace {
bool is_moving(const Body& body) { return body.type != BodyType::Static && body.awake; }
}  // namespace

bool bodies_can_collide(const Body& a, const Body& b) {
  if (!is_moving(a) && !is_moving(b)) return false;
  if (a.type != BodyType::Dynamic && b.type != BodyType::Dynamic) return false;
  return (a.collision_layers & b.collision_layers) != 0;
}

void BroadPhase::find_pairs(const std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
                            const std::vector<Aabb>& bounds, BroadPhaseMethod method,
                            std::vector<BodyPair>& pairs) {
  pairs.clear();
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

}  // namespace impulse2d

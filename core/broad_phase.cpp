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

  sorted_slots_.clear();
  for (std::uint32_t i = 0; i < slot_count; ++i) {
    if (alive[i]) sorted_slots_.push_back(i);
  }
  // Ties on lower.x are broken by slot so the order never depends on the sort's internals.
  std::sort(sorted_slots_.begin(), sorted_slots_.end(), [&](std::uint32_t a, std::uint32_t b) {
    const float ax = bounds[a].lower.x;
    const float bx = bounds[b].lower.x;
    return ax < bx || (ax == bx && a < b);
  });
  const std::size_t count = sorted_slots_.size();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t first = sorted_slots_[i];
    for (std::size_t j = i + 1; j < count; ++j) {
      const std::uint32_t second = sorted_slots_[j];
      if (bounds[second].lower.x > bounds[first].upper.x) break;
      if (bounds[first].overlaps(bounds[second]) && bodies_can_collide(bodies[first], bodies[second])) {
        pairs.emplace_back(std::min(sorted_slots_[i], sorted_slots_[j]),
                           std::max(sorted_slots_[i], sorted_slots_[j]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace impulse2d

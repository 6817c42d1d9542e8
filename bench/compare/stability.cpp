/// @file stability.cpp
#include "bench/compare/stability.h"

#include <algorithm>
#include <cmath>

#include "core/collide.h"

namespace impulse2d::compare {
namespace {

bool finite(const lab::BodyState& state) {
  return std::isfinite(state.position.x) && std::isfinite(state.position.y) &&
         std::isfinite(state.angle);
}

Transform transform_of(const lab::BodyState& state) {
  return Transform{state.position, Rotation::from_angle(state.angle)};
}

}  // namespace

void judge_final_states(const CompareScene& scene, const std::vector<lab::BodyState>& states,
                        Stability& stability) {
  const float degrees_per_radian = 57.29578f;
  for (std::size_t i = 0; i < states.size(); ++i) {
    const lab::BodyState& state = states[i];
    if (!state.dynamic) continue;
    if (!finite(state)) {
      ++stability.non_finite;
      continue;
    }
    const BodyDef& built = scene.bodies[i].def;
    if (scene.judge == Judge::Pyramids) {
      const float side = std::fabs(state.position.x - built.position.x);
      const float turn = std::fabs(state.angle - built.angle) * degrees_per_radian;
      stability.side = std::max(stability.side, side);
      if (side > 0.1f || turn > 5.0f) ++stability.moved;
    } else if (scene.judge == Judge::Pit && !scene.container.contains(state.position)) {
      ++stability.out;
    }
  }
  for (const int top : scene.tops) {
    const lab::BodyState& state = states[static_cast<std::size_t>(top)];
    if (finite(state)) {
      stability.sag = std::max(stability.sag,
                               scene.bodies[static_cast<std::size_t>(top)].def.position.y - state.position.y);
    }
  }
}

float deepest_overlap(const CompareScene& scene, const std::vector<lab::BodyState>& states) {
  struct Entry {
    Aabb bounds;
    int index = 0;
  };
  std::vector<Entry> entries;
  entries.reserve(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!finite(states[i])) continue;
    entries.push_back({compute_aabb(scene.bodies[i].shape, transform_of(states[i])), static_cast<int>(i)});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.bounds.lower.x < b.bounds.lower.x ||
           (a.bounds.lower.x == b.bounds.lower.x && a.index < b.index);
  });
  float deepest = 0.0f;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::size_t a = static_cast<std::size_t>(entries[i].index);
    for (std::size_t j = i + 1; j < entries.size() && entries[j].bounds.lower.x <= entries[i].bounds.upper.x; ++j) {
      const std::size_t b = static_cast<std::size_t>(entries[j].index);
      if (!states[a].dynamic && !states[b].dynamic) continue;
      if (!entries[i].bounds.overlaps(entries[j].bounds)) continue;
      const Manifold manifold = collide(scene.bodies[a].shape, transform_of(states[a]),
                                        scene.bodies[b].shape, transform_of(states[b]));
      for (int p = 0; p < manifold.point_count; ++p) {
        deepest = std::max(deepest, manifold.points[p].depth);
      }
    }
  }
  return deepest;
}

}  // namespace impulse2d::compare

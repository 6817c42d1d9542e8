/// @file scene_random.cpp
#include "demos/scene_random.h"

#include <cmath>

namespace impulse2d::demos {

float SceneRandom::unit() {
  const std::uint32_t top_bits = static_cast<std::uint32_t>(engine_()) >> 8;
  return std::ldexp(static_cast<float>(top_bits), -24);
}

float SceneRandom::uniform(float low, float high) { return low + (high - low) * unit(); }

int SceneRandom::integer(int low, int high) {
  const std::uint32_t span = static_cast<std::uint32_t>(high - low) + 1u;
  // Largest multiple of span that fits in 2^32; draws at or above it would favour small values.
  const std::uint64_t limit = (std::uint64_t{1} << 32) / span * span;
  std::uint64_t draw = engine_();
  while (draw >= limit) draw = engine_();
  return low + static_cast<int>(draw % span);
}

}  // namespace impulse2d::demos

#pragma once
/// @file scene_random.h
/// A seeded random source for scene builders whose numbers are the same on every platform:
/// std::mt19937's output sequence is fixed by the standard, but the std distributions are
/// not, so the conversions to ranges are done here with explicit arithmetic.

#include <cstdint>
#include <random>

namespace impulse2d::demos {

/// Deterministic random numbers for building scenes.
class SceneRandom {
 public:
  /// A generator seeded with `seed`; equal seeds give equal sequences everywhere.
  explicit SceneRandom(std::uint32_t seed) : engine_(seed) {}

  /// A float in [0, 1): the top 24 bits of one 32-bit draw, scaled by 2^-24 (exact in float).
  float unit();
  /// A float in [low, high).
  float uniform(float low, float high);
  /// An integer in [low, high] (inclusive), by rejection so every value is equally likely.
  int integer(int low, int high);

 private:
  std::mt19937 engine_;
};

}  // namespace impulse2d::demos

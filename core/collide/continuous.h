#pragma once
/// @file continuous.h
/// Continuous collision for bullets: a fast body's motion over a step is swept against the
/// bodies it could cross, so it cannot tunnel through a thin wall.

#include "core/solver/body_shapes.h"
#include "core/collide/broad_phase.h"
#include "core/settings.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

/// Swept tests with reusable buffers.
class BulletSweeper {
 public:
  /// For every awake dynamic body marked `is_bullet` that moved more than half its smallest
  /// extent in the last position update of length `dt` seconds: samples its straight-line
  /// motion (start pose = end pose - velocity * dt) at spacings of half that extent against
  /// every non-bullet body whose bounds meet the swept bounds and that it did not already
  /// touch at the start, then bisects between the last free sample and the first overlapping
  /// one (time of impact to 1/1024 of a sample) and moves the bullet back to that pose. Its
  /// velocity is kept: the next step's contact makes the bounce. Returns how many bullets
  /// were moved back. The bodies near a bullet are found in `broad_phase`'s trees, made to
  /// cover every non-bullet body's current bounds first.
  int sweep(std::vector<Body>& bodies, const std::vector<std::uint8_t>& alive,
            const WorldSettings& settings, float dt, BroadPhase& broad_phase);

 private:
  std::vector<std::uint32_t> nearby_;      // slots whose fat boxes meet the swept bounds
  std::vector<std::uint32_t> candidates_;  // bodies the current bullet may hit
};

/// The distance from a shape's centroid to its nearest boundary, metres: the radius of a
/// circle, the smaller half extent of a box, the nearest edge of a polygon.
float smallest_extent(const Shape& shape);

}  // namespace impulse2d

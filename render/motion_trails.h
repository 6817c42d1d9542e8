#pragma once
/// @file motion_trails.h
/// The recent path of chosen bodies, drawn as a polyline that fades towards its oldest point.

#include "core/body.h"
#include "core/debug_draw.h"

#include <cstddef>
#include <deque>
#include <vector>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

/// Remembers the last positions of the bodies it tracks. Call `record` once per drawn frame
/// (or per step) and pass the trails to `FrameOptions::trails`.
class MotionTrails {
 public:
  /// Trails of at most `max_points` positions each (>= 2).
  explicit MotionTrails(std::size_t max_points = 120);

  /// Starts tracking `body` (ignored if already tracked).
  void track(BodyId body);
  /// The tracked bodies, in the order they were added.
  std::vector<BodyId> tracked() const;
  /// Appends each tracked living body's current position (centre of mass, metres); a removed
  /// body's trail stops growing but stays drawn.
  void record(const World& world);
  /// Forgets every recorded position (keeps the tracked set).
  void clear();
  /// True when no body is tracked.
  bool empty() const { return trails_.empty(); }
  /// Draws each trail as segments whose opacity rises from 0 at the oldest point to
  /// `color.a` at the newest.
  void draw(DebugDraw& draw, Color color) const;

 private:
  struct Trail {
    BodyId body;
    std::deque<vec2> points;
  };
  std::size_t max_points_;
  std::vector<Trail> trails_;
};

}  // namespace impulse2d::render

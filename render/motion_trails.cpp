/// @file motion_trails.cpp
#include "render/motion_trails.h"

#include "core/world.h"

#include <algorithm>

namespace impulse2d::render {

MotionTrails::MotionTrails(std::size_t max_points) : max_points_(std::max<std::size_t>(max_points, 2)) {}

void MotionTrails::track(BodyId body) {
  for (const Trail& trail : trails_) {
    if (trail.body == body) return;
  }
  trails_.push_back(Trail{body, {}});
}

std::vector<BodyId> MotionTrails::tracked() const {
  std::vector<BodyId> bodies;
  for (const Trail& trail : trails_) bodies.push_back(trail.body);
  return bodies;
}

void MotionTrails::record(const World& world) {
  for (Trail& trail : trails_) {
    if (!world.is_valid(trail.body)) continue;
    trail.points.push_back(world.body(trail.body).transform.position);
    if (trail.points.size() > max_points_) trail.points.pop_front();
  }
}

void MotionTrails::clear() {
  for (Trail& trail : trails_) trail.points.clear();
}

void MotionTrails::draw(DebugDraw& draw, Color color) const {
  for (const Trail& trail : trails_) {
    const std::size_t count = trail.points.size();
    for (std::size_t i = 1; i < count; ++i) {
      Color faded = color;
      faded.a = color.a * static_cast<float>(i) / static_cast<float>(count - 1);
      draw.draw_segment(trail.points[i - 1], trail.points[i], faded);
    }
  }
}

}  // namespace impulse2d::render

/// @file label_layout.cpp
#include "lab/label_layout.h"

#include <algorithm>
#include <numeric>

namespace impulse2d::lab {
namespace {

struct Rect {
  double left, bottom, right, top;
  bool overlaps(const Rect& other) const {
    return left < other.right && other.left < right && bottom < other.top && other.bottom < top;
  }
};

}  // namespace

std::vector<PlacedLabel> layout_labels(const std::vector<LabelRequest>& requests, double left,
                                       double right, double bottom, double top, double char_width,
                                       double line_height, double point_radius) {
  std::vector<Rect> obstacles;
  for (const LabelRequest& request : requests) {
    obstacles.push_back({request.x - point_radius, request.y - point_radius,
                         request.x + point_radius, request.y + point_radius});
  }
  std::vector<std::size_t> order(requests.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return requests[a].priority > requests[b].priority;
  });

  std::vector<PlacedLabel> placed(requests.size());
  std::vector<Rect> taken;
  for (const std::size_t index : order) {
    const LabelRequest& request = requests[index];
    const double width = char_width * static_cast<double>(request.text.size());
    const double gap = point_radius + 2.0;
    // Candidate left ends and vertical centres: right, left, above, below, then diagonals.
    const double candidates[8][2] = {
        {request.x + gap, request.y},
        {request.x - gap - width, request.y},
        {request.x - width / 2, request.y + gap + line_height / 2},
        {request.x - width / 2, request.y - gap - line_height / 2},
        {request.x + gap, request.y + gap + line_height / 2},
        {request.x + gap, request.y - gap - line_height / 2},
        {request.x - gap - width, request.y + gap + line_height / 2},
        {request.x - gap - width, request.y - gap - line_height / 2}};
    PlacedLabel& result = placed[index];
    result.text = request.text;
    for (const auto& candidate : candidates) {
      const Rect box{candidate[0], candidate[1] - line_height / 2, candidate[0] + width,
                     candidate[1] + line_height / 2};
      if (box.left < left || box.right > right || box.bottom < bottom || box.top > top) continue;
      const auto hits = [&box](const Rect& other) { return box.overlaps(other); };
      if (std::any_of(taken.begin(), taken.end(), hits)) continue;
      if (std::any_of(obstacles.begin(), obstacles.end(), hits)) continue;
      result.placed = true;
      result.x = candidate[0];
      result.y = candidate[1];
      taken.push_back(box);
      break;
    }
  }
  return placed;
}

}  // namespace impulse2d::lab

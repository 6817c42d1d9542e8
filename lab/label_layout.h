#pragma once
/// @file label_layout.h
/// Places text labels next to chart points so that no two labels overlap and no label covers
/// a point: each label tries eight positions around its point, in order of priority.

#include <string>
#include <vector>

namespace impulse2d::lab {

/// A point to label, in pixels from the bottom-left of the canvas.
struct LabelRequest {
  double x = 0.0;     ///< point position, px
  double y = 0.0;     ///< point position, px
  std::string text;   ///< label text
  int priority = 0;   ///< higher is placed first
};

/// Where a label went.
struct PlacedLabel {
  bool placed = false;  ///< false when no candidate position was free
  double x = 0.0;       ///< left end of the text's baseline centre line, px
  double y = 0.0;       ///< vertical centre of the text, px
  std::string text;     ///< label text
};

/// Places `requests` (returned in the same order) inside the box [left, right] x [bottom, top],
/// with text `char_width` px per character and `line_height` px high; every point is an obstacle
/// of `point_radius` px. Deterministic: ties in priority keep the input order.
std::vector<PlacedLabel> layout_labels(const std::vector<LabelRequest>& requests, double left,
                                       double right, double bottom, double top, double char_width,
                                       double line_height, double point_radius);

}  // namespace impulse2d::lab

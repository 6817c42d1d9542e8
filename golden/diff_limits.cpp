/// @file diff_limits.cpp
#include "golden/diff_limits.h"

#include "golden/error.h"

#include <limits>
#include <nlohmann/json.hpp>

namespace impulse2d::golden {

Tolerance tolerance_from_limits(const DiffLimits& limits, const std::string& origin) {
  Tolerance tolerance;
  tolerance.origin = origin;
  if (limits.threshold < 0 || limits.threshold > 255) {
    throw GoldenError("--threshold " + std::to_string(limits.threshold) +
                      ": must be in 0..255 (the largest channel delta that still counts as "
                      "equal)");
  }
  tolerance.max_channel_delta = limits.threshold;
  if (limits.max_diff_pixels && *limits.max_diff_pixels < 0) {
    throw GoldenError("--max-diff-pixels " + std::to_string(*limits.max_diff_pixels) +
                      ": must be >= 0");
  }
  if (limits.max_diff_ratio && !(*limits.max_diff_ratio >= 0.0 && *limits.max_diff_ratio <= 1.0)) {
    throw GoldenError("--max-diff-ratio " + nlohmann::json(*limits.max_diff_ratio).dump() +
                      ": must be in 0..1");
  }
  if (limits.max_diff_pixels || limits.max_diff_ratio) {
    tolerance.max_differing_pixels =
        limits.max_diff_pixels.value_or(std::numeric_limits<std::int64_t>::max());
    tolerance.max_differing_ratio = limits.max_diff_ratio.value_or(1.0);
    tolerance.max_window_pixels = tolerance.window_size * tolerance.window_size;
  }
  for (const std::string& mask : limits.masks) tolerance.masks.push_back(parse_mask(mask, "--mask"));
  return tolerance;
}

}  // namespace impulse2d::golden

#pragma once
/// @file diff_limits.h
/// The tolerance knobs users know from Playwright's toHaveScreenshot, as `impulse2d diff`
/// and a scene file's golden block take them, turned into a `Tolerance`.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "golden/tolerance.h"

namespace impulse2d::golden {

/// Playwright-style limits. With neither count limit given the comparison is strict.
struct DiffLimits {
  /// Most pixels allowed to differ (--max-diff-pixels); unset: no count limit when the
  /// ratio is given.
  std::optional<std::int64_t> max_diff_pixels;
  /// Largest fraction 0..1 of pixels allowed to differ (--max-diff-ratio); unset: no ratio
  /// limit when the count is given.
  std::optional<double> max_diff_ratio;
  /// A pixel differs when a channel changes by more than this, 0..255 (--threshold). Unlike
  /// Playwright's 0..1 colour distance, it is the per-channel delta the golden suite uses.
  int threshold = 0;
  /// "x,y,w,h" rectangles to ignore (--mask, repeatable).
  std::vector<std::string> masks;
};

/// The tolerance the limits describe (no window-density limit: Playwright has none).
/// Throws `GoldenError` naming the option for a negative count, a ratio outside 0..1, a
/// threshold outside 0..255 or a malformed mask.
Tolerance tolerance_from_limits(const DiffLimits& limits, const std::string& origin);

}  // namespace impulse2d::golden

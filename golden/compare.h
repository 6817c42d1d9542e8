#pragma once
/// @file compare.h
/// Golden vs actual: exact match on the decoded RGBA hash first; metrics and the tolerance
/// rules only when the hashes differ.

#include "image/image.h"
#include "golden/tolerance.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// An axis-aligned pixel rectangle, both corners inclusive. Empty when max < min.
struct PixelBox {
  int min_x = 0;   ///< leftmost column
  int min_y = 0;   ///< top row
  int max_x = -1;  ///< rightmost column
  int max_y = -1;  ///< bottom row

  /// True when the box holds no pixel.
  bool empty() const { return max_x < min_x || max_y < min_y; }
};

/// Measurements of a mismatch. "Changed" means any channel differs; "differing" means the
/// largest channel delta exceeds the tolerance's max_channel_delta.
struct DiffMetrics {
  std::int64_t changed_pixels = 0;    ///< unmasked pixels with any channel delta > 0
  std::int64_t masked_pixels = 0;     ///< changed pixels inside the tolerance's masks (ignored)
  std::int64_t differing_pixels = 0;  ///< pixels beyond the per-channel tolerance
  double differing_ratio = 0.0;       ///< differing_pixels / pixel count
  int max_channel_delta = 0;          ///< largest delta of any channel of any pixel, 0-255
  std::array<int, 4> channel_max_delta{};  ///< largest delta per channel: R, G, B, A
  bool alpha_only = false;  ///< every changed pixel has equal RGB and a different alpha
  int window_width = 0;         ///< width of the density window used (clamped to the image)
  int window_height = 0;        ///< height of the density window used
  int worst_window_pixels = 0;  ///< most differing pixels found in any one window
  int worst_window_x = 0;       ///< left column of that window
  int worst_window_y = 0;       ///< top row of that window
  PixelBox differing_box;       ///< bounding box of the differing pixels
};

/// What a comparison found.
enum class CompareOutcome {
  ExactMatch,        ///< same size and same RGBA hash
  WithinTolerance,   ///< pixels differ, every tolerance rule holds
  ExceedsTolerance,  ///< at least one tolerance rule fails
  SizeMismatch,      ///< widths or heights differ; nothing else is measured
};

/// One tolerance rule.
enum class ToleranceRule {
  DifferingPixels,  ///< Tolerance::max_differing_pixels
  DifferingRatio,   ///< Tolerance::max_differing_ratio
  WindowDensity,    ///< Tolerance::max_window_pixels over window_size windows
};

/// A rule that failed, with the measured value and its limit.
struct RuleViolation {
  ToleranceRule rule = ToleranceRule::DifferingPixels;  ///< which rule
  double measured = 0.0;  ///< what the comparison found
  double limit = 0.0;     ///< what the tolerance allows
  /// e.g. "worst 8x8 window, top-left (37,29), has 25 differing pixels; limit 4
  /// (override from sidecar 'circles/start.json')"
  std::string text;
};

/// The result of `compare_images`.
struct CompareResult {
  CompareOutcome outcome = CompareOutcome::ExactMatch;  ///< the verdict
  int expected_width = 0;           ///< golden width
  int expected_height = 0;          ///< golden height
  int actual_width = 0;             ///< actual width
  int actual_height = 0;            ///< actual height
  std::uint64_t expected_hash = 0;  ///< `Image::hash()` of the golden
  std::uint64_t actual_hash = 0;    ///< `Image::hash()` of the actual image
  DiffMetrics metrics;  ///< filled when the sizes agree and the hashes differ
  std::vector<RuleViolation> violations;  ///< failed rules, in ToleranceRule order
  Tolerance tolerance;  ///< the limits applied

  /// True for ExactMatch and WithinTolerance.
  bool passed() const;
  /// One paragraph: the verdict, the metrics, and each failed rule with its limit and where
  /// the limit came from.
  std::string message() const;
};

/// Largest of the four channel deltas of pixel (x, y); both images must hold that pixel.
int max_channel_delta_at(const image::Image& expected, const image::Image& actual, int x, int y);

/// Compares an actual image with its golden under `tolerance`. Throws `GoldenError` when
/// either image's pixel buffer does not hold width * height * 4 bytes.
CompareResult compare_images(const image::Image& expected, const image::Image& actual,
                             const Tolerance& tolerance = Tolerance{});

}  // namespace impulse2d::golden

/// @file compare.cpp
#include "golden/compare.h"

#include "golden/error.h"
#include "image/hex_hash.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace impulse2d::golden {

namespace {

std::string box_text(const PixelBox& box) {
  std::ostringstream text;
  text << "(" << box.min_x << "," << box.min_y << ")-(" << box.max_x << "," << box.max_y << ")";
  return text.str();
}

/// Fills the window fields of `metrics` from a 0/1 mask of differing pixels, using a
/// summed-area table so every window position costs O(1).
void find_worst_window(const std::vector<std::uint8_t>& mask, int width, int height,
                       int window_size, DiffMetrics& metrics) {
  metrics.window_width = std::min(window_size, width);
  metrics.window_height = std::min(window_size, height);
  const auto stride = static_cast<std::size_t>(width) + 1;
  std::vector<std::int32_t> sums(stride * (static_cast<std::size_t>(height) + 1), 0);
  auto at = [&](int x, int y) -> std::int32_t& {
    return sums[static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x)];
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t index = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                static_cast<std::size_t>(x);
      at(x + 1, y + 1) = mask[index] + at(x, y + 1) + at(x + 1, y) - at(x, y);
    }
  }
  for (int y = 0; y + metrics.window_height <= height; ++y) {
    for (int x = 0; x + metrics.window_width <= width; ++x) {
      const int x1 = x + metrics.window_width;
      const int y1 = y + metrics.window_height;
      const int count = at(x1, y1) - at(x, y1) - at(x1, y) + at(x, y);
      if (count > metrics.worst_window_pixels) {
        metrics.worst_window_pixels = count;
        metrics.worst_window_x = x;
        metrics.worst_window_y = y;
      }
    }
  }
}

DiffMetrics measure(const image::Image& expected, const image::Image& actual, const Tolerance& tolerance) {
  DiffMetrics metrics;
  const int width = expected.width;
  const int height = expected.height;
  std::vector<std::uint8_t> mask(expected.pixel_count(), 0);
  bool any_rgb_change = false;
  PixelBox& box = metrics.differing_box;
  box = PixelBox{width, height, -1, -1};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t offset = expected.offset(x, y);
      if (std::any_of(tolerance.masks.begin(), tolerance.masks.end(),
                      [x, y](const MaskRect& rect) { return rect.contains(x, y); })) {
        if (max_channel_delta_at(expected, actual, x, y) > 0) ++metrics.masked_pixels;
        continue;
      }
      int pixel_delta = 0;
      for (int channel = 0; channel < image::kChannels; ++channel) {
        const int delta = std::abs(int{expected.rgba[offset + channel]} -
                                   int{actual.rgba[offset + channel]});
        metrics.channel_max_delta[channel] = std::max(metrics.channel_max_delta[channel], delta);
        if (channel < 3 && delta > 0) any_rgb_change = true;
        pixel_delta = std::max(pixel_delta, delta);
      }
      if (pixel_delta == 0) continue;
      ++metrics.changed_pixels;
      if (pixel_delta <= tolerance.max_channel_delta) continue;
      ++metrics.differing_pixels;
      mask[offset / image::kChannels] = 1;
      box.min_x = std::min(box.min_x, x);
      box.min_y = std::min(box.min_y, y);
      box.max_x = std::max(box.max_x, x);
      box.max_y = std::max(box.max_y, y);
    }
  }
  if (box.empty()) box = PixelBox{};
  metrics.max_channel_delta =
      *std::max_element(metrics.channel_max_delta.begin(), metrics.channel_max_delta.end());
  metrics.alpha_only = metrics.changed_pixels > 0 && !any_rgb_change;
  const auto pixel_count = static_cast<double>(expected.pixel_count());
  metrics.differing_ratio =
      pixel_count > 0.0 ? static_cast<double>(metrics.differing_pixels) / pixel_count : 0.0;
  find_worst_window(mask, width, height, std::max(tolerance.window_size, 1), metrics);
  return metrics;
}

std::vector<RuleViolation> check_rules(const DiffMetrics& metrics, const Tolerance& tolerance) {
  std::vector<RuleViolation> violations;
  const std::string origin = " (" + tolerance.describe_origin() + ")";
  if (metrics.differing_pixels > tolerance.max_differing_pixels) {
    std::ostringstream text;
    text << metrics.differing_pixels << " differing pixels; limit "
         << tolerance.max_differing_pixels << origin;
    violations.push_back({ToleranceRule::DifferingPixels,
                          static_cast<double>(metrics.differing_pixels),
                          static_cast<double>(tolerance.max_differing_pixels), text.str()});
  }
  if (metrics.differing_ratio > tolerance.max_differing_ratio) {
    std::ostringstream text;
    text << "differing ratio " << metrics.differing_ratio << "; limit "
         << tolerance.max_differing_ratio << origin;
    violations.push_back({ToleranceRule::DifferingRatio, metrics.differing_ratio,
                          tolerance.max_differing_ratio, text.str()});
  }
  if (metrics.worst_window_pixels > tolerance.max_window_pixels) {
    std::ostringstream text;
    text << "worst " << metrics.window_width << "x" << metrics.window_height
         << " window, top-left (" << metrics.worst_window_x << "," << metrics.worst_window_y
         << "), has " << metrics.worst_window_pixels << " differing pixels; limit "
         << tolerance.max_window_pixels << origin;
    violations.push_back({ToleranceRule::WindowDensity,
                          static_cast<double>(metrics.worst_window_pixels),
                          static_cast<double>(tolerance.max_window_pixels), text.str()});
  }
  return violations;
}

}  // namespace

int max_channel_delta_at(const image::Image& expected, const image::Image& actual, int x, int y) {
  const std::size_t offset = expected.offset(x, y);
  int largest = 0;
  for (int channel = 0; channel < image::kChannels; ++channel) {
    largest = std::max(largest, std::abs(int{expected.rgba[offset + channel]} -
                                         int{actual.rgba[offset + channel]}));
  }
  return largest;
}

CompareResult compare_images(const image::Image& expected, const image::Image& actual,
                             const Tolerance& tolerance) {
  for (const image::Image* image : {&expected, &actual}) {
    if (image->width < 0 || image->height < 0 ||
        image->rgba.size() != image->pixel_count() * image::kChannels) {
      throw GoldenError("compare_images: " + std::string(image == &expected ? "golden" : "actual") +
                        " image " + std::to_string(image->width) + "x" +
                        std::to_string(image->height) + " holds " +
                        std::to_string(image->rgba.size()) + " bytes, not width*height*4");
    }
  }
  CompareResult result;
  result.expected_width = expected.width;
  result.expected_height = expected.height;
  result.actual_width = actual.width;
  result.actual_height = actual.height;
  result.expected_hash = expected.hash();
  result.actual_hash = actual.hash();
  result.tolerance = tolerance;
  if (expected.width != actual.width || expected.height != actual.height) {
    result.outcome = CompareOutcome::SizeMismatch;
    return result;
  }
  if (result.expected_hash == result.actual_hash) {
    result.outcome = CompareOutcome::ExactMatch;
    return result;
  }
  result.metrics = measure(expected, actual, tolerance);
  result.violations = check_rules(result.metrics, tolerance);
  result.outcome = result.violations.empty() ? CompareOutcome::WithinTolerance
                                             : CompareOutcome::ExceedsTolerance;
  return result;
}

bool CompareResult::passed() const {
  return outcome == CompareOutcome::ExactMatch || outcome == CompareOutcome::WithinTolerance;
}

std::string CompareResult::message() const {
  std::ostringstream text;
  switch (outcome) {
    case CompareOutcome::ExactMatch:
      text << "exact match (RGBA hash " << image::to_hex_hash(actual_hash) << ")";
      return text.str();
    case CompareOutcome::SizeMismatch:
      text << "size mismatch: golden is " << expected_width << "x" << expected_height
           << ", actual is " << actual_width << "x" << actual_height;
      return text.str();
    case CompareOutcome::WithinTolerance:
      text << "within tolerance (" << tolerance.describe_origin() << "): ";
      break;
    case CompareOutcome::ExceedsTolerance:
      text << "pixels differ: ";
      break;
  }
  text << metrics.changed_pixels << " changed pixels, " << metrics.differing_pixels
       << " beyond channel delta " << tolerance.max_channel_delta << " (ratio "
       << metrics.differing_ratio << "); max channel delta " << metrics.max_channel_delta
       << " (R " << metrics.channel_max_delta[0] << ", G " << metrics.channel_max_delta[1]
       << ", B " << metrics.channel_max_delta[2] << ", A " << metrics.channel_max_delta[3] << ")";
  if (!metrics.differing_box.empty()) {
    text << "; changes within " << box_text(metrics.differing_box);
  }
  if (metrics.alpha_only) text << "; only alpha differs, RGB is identical";
  if (metrics.masked_pixels > 0) {
    text << "; " << metrics.masked_pixels << " changed pixels inside "
         << tolerance.masks.size() << " mask" << (tolerance.masks.size() == 1 ? "" : "s")
         << " ignored";
  }
  for (const RuleViolation& violation : violations) text << "; " << violation.text;
  return text.str();
}

}  // namespace impulse2d::golden

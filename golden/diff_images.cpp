/// @file diff_images.cpp
#include "golden/diff_images.h"

#include "golden/compare.h"

#include <algorithm>
#include <cassert>

namespace impulse2d::golden {

namespace {

constexpr image::Rgba kBeyondTolerance{255, 0, 0, 255};
constexpr image::Rgba kWithinTolerance{255, 200, 0, 255};

/// `expected`'s pixel as an opaque light grey: Rec. 601 luma, faded three quarters to white.
image::Rgba dimmed(const image::Image& image, int x, int y) {
  const image::Rgba colour = image.pixel(x, y);
  const int luma = (299 * colour.r + 587 * colour.g + 114 * colour.b) / 1000;
  const auto grey = static_cast<std::uint8_t>(255 - (255 - luma) / 4);
  return image::Rgba{grey, grey, grey, 255};
}

/// Black at 0, through red and yellow, to white at 1.
image::Rgba heat(double t) {
  auto ramp = [t](double start) {
    return static_cast<std::uint8_t>(std::clamp((3.0 * t - start) * 255.0, 0.0, 255.0) + 0.5);
  };
  return image::Rgba{ramp(0.0), ramp(1.0), ramp(2.0), 255};
}

}  // namespace

image::Image diff_overlay(const image::Image& expected, const image::Image& actual, int max_channel_delta) {
  assert(expected.width == actual.width && expected.height == actual.height);
  image::Image overlay = image::make_image(expected.width, expected.height, image::Rgba{});
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int delta = max_channel_delta_at(expected, actual, x, y);
      image::Rgba colour = dimmed(expected, x, y);
      if (delta > max_channel_delta) {
        colour = kBeyondTolerance;
      } else if (delta > 0) {
        colour = kWithinTolerance;
      }
      overlay.set_pixel(x, y, colour);
    }
  }
  return overlay;
}

image::Image diff_heatmap(const image::Image& expected, const image::Image& actual) {
  assert(expected.width == actual.width && expected.height == actual.height);
  std::vector<int> deltas(expected.pixel_count(), 0);
  int largest = 0;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int delta = max_channel_delta_at(expected, actual, x, y);
      deltas[expected.offset(x, y) / image::kChannels] = delta;
      largest = std::max(largest, delta);
    }
  }
  image::Image heatmap = image::make_image(expected.width, expected.height, image::Rgba{0, 0, 0, 255});
  if (largest == 0) return heatmap;
  for (int y = 0; y < expected.height; ++y) {
    for (int x = 0; x < expected.width; ++x) {
      const int delta = deltas[expected.offset(x, y) / image::kChannels];
      heatmap.set_pixel(x, y, heat(static_cast<double>(delta) / largest));
    }
  }
  return heatmap;
}

}  // namespace impulse2d::golden

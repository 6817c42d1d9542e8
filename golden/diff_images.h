#pragma once
/// @file diff_images.h
/// Pictures of a difference, for people: an overlay that shows where, a heatmap that shows
/// how much.

#include "image/image.h"

namespace impulse2d::golden {

/// The golden dimmed to light grey, with pixels beyond `max_channel_delta` in red and
/// pixels that changed within it in yellow. Opaque. Both images must have the same size.
image::Image diff_overlay(const image::Image& expected, const image::Image& actual, int max_channel_delta);

/// Each pixel's largest channel delta, scaled so the image's largest delta maps to full
/// intensity, on a black-red-yellow-white ramp; unchanged pixels are black. Opaque. Both
/// images must have the same size.
image::Image diff_heatmap(const image::Image& expected, const image::Image& actual);

}  // namespace impulse2d::golden

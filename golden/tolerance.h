#pragma once
/// @file tolerance.h
/// How far an actual image may stray from its golden. Layered, and none of the layers grows
/// with the image size: a bigger frame does not buy a bigger blob of wrong pixels.

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// A rectangle of pixels a comparison ignores (a clock, a frame counter): x, y of its
/// top-left pixel (rows counted from the top), width and height in pixels.
struct MaskRect {
  int x = 0;       ///< leftmost column
  int y = 0;       ///< top row
  int width = 0;   ///< columns, >= 1
  int height = 0;  ///< rows, >= 1

  /// True when pixel (px, py) lies inside.
  bool contains(int px, int py) const {
    return px >= x && py >= y && px - x < width && py - y < height;
  }
};

/// Limits an image comparison is held to. Each layer must hold. The default is strict: any
/// pixel whose channels differ at all fails.
struct Tolerance {
  /// A pixel counts as differing when the largest of its four channel deltas (0-255) exceeds
  /// this; pixels within it count as equal for every other rule.
  int max_channel_delta = 0;
  /// Largest number of differing pixels allowed in the whole image.
  std::int64_t max_differing_pixels = 0;
  /// Largest fraction (0-1) of the image's pixels allowed to differ.
  double max_differing_ratio = 0.0;
  /// Side, in pixels, of the square window of the density rule (clamped to the image size).
  int window_size = 8;
  /// Most differing pixels any window_size x window_size window may hold: a compact cluster
  /// fails even when the image-wide count and ratio are within their limits.
  int max_window_pixels = 0;
  /// Regions whose pixels count as equal whatever they hold.
  std::vector<MaskRect> masks;
  /// Where these limits came from when they are not the strict default, e.g.
  /// "sidecar 'circles/start.json'"; named in failure messages.
  std::string origin;

  /// True when every limit is the strict default and nothing is masked (window_size does
  /// not matter then).
  bool is_strict() const;
  /// "strict default" or "override from <origin>", for failure messages.
  std::string describe_origin() const;
};

/// Reads limits from a JSON object whose keys are the field names above (all optional;
/// missing keys keep the strict default); "masks" is an array of [x, y, width, height]. `origin` is stored and used in error messages.
/// Throws `GoldenError` naming `origin` and the field for unknown keys, wrong types and
/// out-of-range values, and when max_differing_pixels, max_differing_ratio and
/// max_window_pixels are not either all 0 or all above 0 (a lone loosened layer is a no-op).
Tolerance tolerance_from_json(const nlohmann::json& object, const std::string& origin);

/// Parses "x,y,w,h" (non-negative integers, w and h at least 1). Throws `GoldenError`
/// naming `origin` (e.g. "--mask") and the reason.
MaskRect parse_mask(const std::string& text, const std::string& origin);

/// The limits as a JSON object with every field (origin excluded; masks only when any).
nlohmann::json tolerance_to_json(const Tolerance& tolerance);

}  // namespace impulse2d::golden

#pragma once
/// @file frame.h
/// One rendered image in memory: 8-bit RGBA, rows top to bottom, always opaque.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impulse2d::render {

/// An 8-bit RGBA pixel.
struct Pixel {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< alpha; rendered frames are opaque (255)
  /// Channel-wise equality.
  bool operator==(const Pixel& other) const {
    return r == other.r && g == other.g && b == other.b && a == other.a;
  }
  /// Opposite of ==.
  bool operator!=(const Pixel& other) const { return !(*this == other); }
};

/// An RGBA8 image. Row 0 is the top of the picture (as in a PNG file and in
/// `golden::Image`); the bottom-up GL buffer is flipped once, when the frame is read back.
struct Frame {
  int width = 0;                   ///< pixels per row
  int height = 0;                  ///< rows
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row-major, no padding

  /// Resizes to width x height (contents unspecified). Keeps the allocation when it fits.
  void resize(int new_width, int new_height);
  /// Bytes per row (width * 4).
  std::size_t stride() const { return static_cast<std::size_t>(width) * 4; }
  /// The pixel at column `x` and row `y` (0 = top). Both must lie inside the frame.
  Pixel pixel(int x, int y) const;
  /// True when every pixel has alpha 255.
  bool is_opaque() const;
  /// 64-bit FNV-1a over width, height (4 little-endian bytes each) and the RGBA bytes, the
  /// same definition as `golden::rgba_hash`, so a frame and its decoded PNG hash alike.
  std::uint64_t hash() const;
};

}  // namespace impulse2d::render

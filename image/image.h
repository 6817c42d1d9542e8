#pragma once
/// @file image.h
/// The project's one image type: 8-bit RGBA in memory, rows top to bottom, with the PNG text
/// metadata that travels with it. The renderer draws into it (render::Frame names it), the
/// golden tools compare it, the PNG functions (image/png.h) read and write it.

#include "image/png_text.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace impulse2d::image {

/// Channels per pixel: red, green, blue, alpha, in that order.
inline constexpr int kChannels = 4;

/// An RGBA colour with 8 bits per channel.
struct Rgba {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< alpha, 255 opaque
  /// Channel-wise equality.
  bool operator==(const Rgba& other) const {
    return r == other.r && g == other.g && b == other.b && a == other.a;
  }
  /// Opposite of ==.
  bool operator!=(const Rgba& other) const { return !(*this == other); }
};

/// An 8-bit RGBA image. Row 0 is the top of the picture, as in a PNG file; the renderer flips
/// GL's bottom-up buffer once, when it reads a frame back.
struct Image {
  int width = 0;                   ///< pixels per row
  int height = 0;                  ///< rows
  std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes, row-major, no padding
  /// tEXt metadata, written with the PNG and read back from it; not part of `hash()`.
  PngText text;

  /// Resizes to width x height (contents unspecified). Keeps the allocation when it fits.
  void resize(int new_width, int new_height);
  /// Number of pixels (width * height).
  std::size_t pixel_count() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  /// Bytes per row (width * 4).
  std::size_t stride() const { return static_cast<std::size_t>(width) * kChannels; }
  /// Index of the first byte (red) of pixel (x, y) in `rgba`.
  std::size_t offset(int x, int y) const {
    return static_cast<std::size_t>(y) * stride() + static_cast<std::size_t>(x) * kChannels;
  }
  /// The pixel at column `x` and row `y` (0 = top). Both must lie inside the image.
  Rgba pixel(int x, int y) const;
  /// Sets the pixel at column `x` and row `y`, which must lie inside the image.
  void set_pixel(int x, int y, Rgba colour);
  /// True when every pixel has alpha 255.
  bool is_opaque() const;
  /// 64-bit FNV-1a over width, height (4 little-endian bytes each) and the RGBA bytes: the
  /// identity of the content, independent of how a PNG of it was compressed.
  std::uint64_t hash() const;
};

/// A width x height image filled with one colour. Throws `ImageError` for negative sizes.
Image make_image(int width, int height, Rgba fill);

}  // namespace impulse2d::image

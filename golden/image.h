#pragma once
/// @file image.h
/// An RGBA8 image in memory, its PNG files and its content hash.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "golden/png_text.h"

namespace impulse2d::golden {

/// Channels per pixel: red, green, blue, alpha, in that order.
inline constexpr int kChannels = 4;

/// An 8-bit RGBA image, rows top to bottom, no padding between rows.
struct Image {
  int width = 0;                     ///< pixels per row
  int height = 0;                    ///< rows
  std::vector<std::uint8_t> pixels;  ///< width * height * 4 bytes, RGBA, row-major
  /// tEXt metadata, written by `save_png` and read by `load_png`; not part of `rgba_hash`.
  PngText text;

  /// Number of pixels (width * height).
  std::size_t pixel_count() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  /// Index of the first byte (red) of pixel (x, y) in `pixels`.
  std::size_t offset(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
            static_cast<std::size_t>(x)) * kChannels;
  }
};

/// An RGBA colour with 8 bits per channel.
struct Rgba {
  std::uint8_t r = 0;    ///< red
  std::uint8_t g = 0;    ///< green
  std::uint8_t b = 0;    ///< blue
  std::uint8_t a = 255;  ///< alpha, 255 opaque
};

/// A width x height image filled with one colour. Throws `GoldenError` for negative sizes.
Image make_image(int width, int height, Rgba fill);

/// Sets pixel (x, y), which must lie inside the image.
void set_pixel(Image& image, int x, int y, Rgba colour);

/// Pixel (x, y), which must lie inside the image.
Rgba get_pixel(const Image& image, int x, int y);

/// 64-bit FNV-1a over width, height (each as 4 little-endian bytes) and the RGBA bytes: the
/// identity of the decoded content, independent of how the PNG was compressed.
std::uint64_t rgba_hash(const Image& image);

/// Decodes a PNG file into RGBA8 (grey, RGB and 16-bit files are converted), with its tEXt
/// chunks in `text`. Throws
/// `GoldenError` naming the file when it cannot be read or decoded.
Image load_png(const std::filesystem::path& file);

/// Encodes as an RGBA8 PNG in memory, with `image.text` as tEXt chunks.
std::vector<std::uint8_t> encode_png(const Image& image);

/// Writes an RGBA8 PNG, through a temporary file renamed into place so a reader never sees
/// half a file. Creates missing parent directories. Throws `GoldenError` on failure.
void save_png(const std::filesystem::path& file, const Image& image);

}  // namespace impulse2d::golden

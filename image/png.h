#pragma once
/// @file png.h
/// The project's one PNG path: images to 8-bit PNG bytes and files (RGB when every pixel is
/// opaque, as frames are, else RGBA; with their tEXt chunks) and back. Encoding is stb_image_write's PNG writer with libdeflate as its
/// compressor and one fixed row filter (none: flat-coloured frames deflate best unfiltered);
/// decoding is stb_image, after a structure check (image/png_check.h).

#include "image/image.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace impulse2d::image {

/// How hard PNG data is compressed.
enum class PngCompression {
  Fast,   ///< libdeflate level 1: frame sequences, where encoding time counts
  Small,  ///< libdeflate level 12: files kept in a repository (goldens) or a report
};

/// Encodes `image` as an 8-bit PNG with `image.text` as tEXt chunks: RGB (colour type 2) when
/// every pixel's alpha is 255, else RGBA (colour type 6); decoding gives the same RGBA bytes. Thread-safe. Throws
/// `ImageError` for an empty or inconsistent image or when the encoder fails.
std::vector<std::uint8_t> encode_png(const Image& image,
                                     PngCompression compression = PngCompression::Small);

/// Decodes PNG bytes into RGBA8 (grey, RGB and 16-bit files are converted), with the tEXt
/// chunks in `text`. Throws `ImageError` naming `source` (the file the bytes came from) when
/// the bytes are not a well-formed PNG inside the decoding budget.
Image decode_png(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& source);

/// `decode_png` of a file's bytes. Throws `ImageError` naming the file when it cannot be read
/// or decoded.
Image load_png(const std::filesystem::path& file);

/// Writes `image` as a PNG through a temporary file renamed into place, so a reader never sees
/// half a file. Creates missing parent directories. Throws `ImageError` on failure.
void save_png(const std::filesystem::path& file, const Image& image,
              PngCompression compression = PngCompression::Small);

}  // namespace impulse2d::image

#pragma once
/// @file png_encoder.h
/// Frames to PNG bytes and files. Both paths use stb_image_write's PNG writer; the fast one
/// swaps its deflate for libdeflate at level 1 and uses one fixed row filter instead of
/// trying all five per row.

#include "render/frame.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace impulse2d::render {

/// How PNG data is compressed.
enum class PngEncoding {
  Fast,        ///< libdeflate level 1 behind stb (STBIW_ZLIB_COMPRESS), no row filter
  StbDefault,  ///< stb's own deflate with its per-row best-filter search (the baseline)
};

/// Encodes `frame` as an 8-bit RGBA PNG. Thread-safe. Throws `RenderError` for an empty or
/// inconsistent frame or when the encoder fails.
std::vector<std::uint8_t> encode_png(const Frame& frame, PngEncoding encoding = PngEncoding::Fast);

/// Writes `bytes` to `path` through a temporary file in the same directory that is renamed
/// into place, so readers never see half a file. On failure nothing is left behind and
/// `RenderError` names the path and the reason.
void write_file_atomically(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

/// `encode_png` then `write_file_atomically`.
void write_png(const std::filesystem::path& path, const Frame& frame,
               PngEncoding encoding = PngEncoding::Fast);

}  // namespace impulse2d::render

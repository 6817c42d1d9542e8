#pragma once
/// @file png_check.h
/// Checks a PNG's structure before it is decoded: the signature, every chunk's length and
/// CRC, IHDR first with dimensions inside the decoding budget, IEND last. stb_image skips
/// CRCs and allocates whatever the header asks for; this check refuses both up front.

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::image {

/// Largest side of a PNG that is decoded, pixels.
constexpr std::uint32_t kMaxPngSide = 16384;
/// Most pixels of a PNG that is decoded (256 MiB of RGBA).
constexpr std::uint64_t kMaxPngPixels = 64ull * 1024 * 1024;

/// Empty when `bytes` is a well-formed PNG inside the budget; otherwise the reason, e.g.
/// "chunk IDAT at byte 33: CRC mismatch (the file is corrupt)".
std::string png_structure_problem(const std::vector<std::uint8_t>& bytes);

}  // namespace impulse2d::image

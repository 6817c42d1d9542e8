/// @file png_check.cpp
#include "image/png_check.h"

#include <libdeflate.h>

#include <algorithm>

namespace impulse2d::image {
namespace {

std::uint32_t big_endian_u32(const std::uint8_t* bytes) {
  return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) |
         (std::uint32_t{bytes[2]} << 8) | std::uint32_t{bytes[3]};
}

}  // namespace

std::string png_structure_problem(const std::vector<std::uint8_t>& bytes) {
  static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin())) {
    return "not a PNG file (no PNG signature)";
  }
  std::size_t at = 8;
  bool first = true;
  while (true) {
    if (bytes.size() - at < 12) return "truncated at byte " + std::to_string(at) + " (no IEND)";
    const std::uint32_t length = big_endian_u32(&bytes[at]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    const std::string where = "chunk " + type + " at byte " + std::to_string(at);
    if (length > bytes.size() - at - 12) return where + ": length runs past the end of the file";
    const std::uint32_t stored = big_endian_u32(&bytes[at + 8 + length]);
    const std::uint32_t computed = libdeflate_crc32(0, &bytes[at + 4], length + 4);
    if (stored != computed) {
      return where + ": CRC mismatch (the file is corrupt)";
    }
    if (first) {
      if (type != "IHDR" || length != 13) return "the first chunk is not a valid IHDR";
      const std::uint32_t width = big_endian_u32(&bytes[at + 8]);
      const std::uint32_t height = big_endian_u32(&bytes[at + 12]);
      if (width == 0 || height == 0 || width > kMaxPngSide || height > kMaxPngSide ||
          std::uint64_t{width} * height > kMaxPngPixels) {
        return "the header says " + std::to_string(width) + "x" + std::to_string(height) +
               " pixels; the limit is " + std::to_string(kMaxPngSide) + " a side and " +
               std::to_string(kMaxPngPixels) + " in all";
      }
      first = false;
    }
    at += 12 + length;
    if (type == "IEND") return {};
  }
}

}  // namespace impulse2d::image

/// @file png_text.cpp
#include "image/png_text.h"

#include <libdeflate.h>

#include "image/error.h"

namespace impulse2d::image {

namespace {

constexpr std::size_t kSignatureSize = 8;

std::uint32_t read_u32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return static_cast<std::uint32_t>(bytes[at]) << 24 | static_cast<std::uint32_t>(bytes[at + 1]) << 16 |
         static_cast<std::uint32_t>(bytes[at + 2]) << 8 | static_cast<std::uint32_t>(bytes[at + 3]);
}

void append_u32(std::vector<std::uint8_t>& bytes, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) bytes.push_back(static_cast<std::uint8_t>(value >> shift));
}

}  // namespace

std::vector<std::uint8_t> with_png_text(const std::vector<std::uint8_t>& png, const PngText& text) {
  if (png.size() < kSignatureSize + 12) throw ImageError("with_png_text: not a PNG");
  const std::size_t after_ihdr = kSignatureSize + 12 + read_u32(png, kSignatureSize);
  std::vector<std::uint8_t> chunks;
  for (const auto& [keyword, value] : text) {
    if (keyword.empty() || keyword.size() > 79 || keyword.find('\0') != std::string::npos ||
        value.find('\0') != std::string::npos) {
      throw ImageError("PNG text keyword '" + keyword +
                        "' must have 1..79 characters and neither it nor its text a NUL byte");
    }
    std::vector<std::uint8_t> data = {'t', 'E', 'X', 't'};
    data.insert(data.end(), keyword.begin(), keyword.end());
    data.push_back(0);
    data.insert(data.end(), value.begin(), value.end());
    append_u32(chunks, static_cast<std::uint32_t>(data.size() - 4));
    chunks.insert(chunks.end(), data.begin(), data.end());
    append_u32(chunks, static_cast<std::uint32_t>(
                           libdeflate_crc32(0, data.data(), data.size())));
  }
  std::vector<std::uint8_t> result(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(after_ihdr));
  result.insert(result.end(), chunks.begin(), chunks.end());
  result.insert(result.end(), png.begin() + static_cast<std::ptrdiff_t>(after_ihdr), png.end());
  return result;
}

PngText read_png_text(const std::vector<std::uint8_t>& png) {
  PngText text;
  std::size_t at = kSignatureSize;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = read_u32(png, at);
    if (at + 12 + length > png.size()) break;
    const std::string type(png.begin() + static_cast<std::ptrdiff_t>(at + 4),
                           png.begin() + static_cast<std::ptrdiff_t>(at + 8));
    if (type == "tEXt") {
      const auto begin = png.begin() + static_cast<std::ptrdiff_t>(at + 8);
      const std::string data(begin, begin + length);
      const std::size_t nul = data.find('\0');
      if (nul != std::string::npos && nul > 0) text.emplace(data.substr(0, nul), data.substr(nul + 1));
    }
    at += 12 + length;
  }
  return text;
}

}  // namespace impulse2d::image

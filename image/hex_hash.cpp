/// @file hex_hash.cpp
#include "image/hex_hash.h"

namespace impulse2d::image {

std::string to_hex_hash(std::uint64_t hash) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i) {
    text[static_cast<std::size_t>(i)] = kDigits[hash & 0xfu];
    hash >>= 4;
  }
  return text;
}

std::optional<std::uint64_t> parse_hex_hash(const std::string& text) {
  if (text.size() != 16) return std::nullopt;
  std::uint64_t hash = 0;
  for (char c : text) {
    unsigned digit = 0;
    if (c >= '0' && c <= '9') {
      digit = static_cast<unsigned>(c - '0');
    } else if (c >= 'a' && c <= 'f') {
      digit = static_cast<unsigned>(c - 'a' + 10);
    } else if (c >= 'A' && c <= 'F') {
      digit = static_cast<unsigned>(c - 'A' + 10);
    } else {
      return std::nullopt;
    }
    hash = (hash << 4) | digit;
  }
  return hash;
}

}  // namespace impulse2d::image

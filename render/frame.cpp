/// @file frame.cpp
#include "render/frame.h"

#include <cassert>

namespace impulse2d::render {

namespace {

constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

std::uint64_t fnv1a_byte(std::uint64_t hash, std::uint8_t byte) { return (hash ^ byte) * kFnvPrime; }

std::uint64_t fnv1a_u32(std::uint64_t hash, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) {
    hash = fnv1a_byte(hash, static_cast<std::uint8_t>(value >> shift));
  }
  return hash;
}

}  // namespace

void Frame::resize(int new_width, int new_height) {
  assert(new_width >= 0 && new_height >= 0);
  width = new_width;
  height = new_height;
  rgba.resize(stride() * static_cast<std::size_t>(height));
}

Pixel Frame::pixel(int x, int y) const {
  assert(x >= 0 && x < width && y >= 0 && y < height);
  const std::uint8_t* p = &rgba[static_cast<std::size_t>(y) * stride() + static_cast<std::size_t>(x) * 4];
  return Pixel{p[0], p[1], p[2], p[3]};
}

bool Frame::is_opaque() const {
  for (std::size_t i = 3; i < rgba.size(); i += 4) {
    if (rgba[i] != 255) return false;
  }
  return true;
}

std::uint64_t Frame::hash() const {
  std::uint64_t value = kFnvOffsetBasis;
  value = fnv1a_u32(value, static_cast<std::uint32_t>(width));
  value = fnv1a_u32(value, static_cast<std::uint32_t>(height));
  for (std::uint8_t byte : rgba) value = fnv1a_byte(value, byte);
  return value;
}

}  // namespace impulse2d::render

/// @file image.cpp
#include "image/image.h"

#include "image/error.h"

#include <cassert>
#include <string>

namespace impulse2d::image {

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

void Image::resize(int new_width, int new_height) {
  assert(new_width >= 0 && new_height >= 0);
  width = new_width;
  height = new_height;
  rgba.resize(stride() * static_cast<std::size_t>(height));
}

Rgba Image::pixel(int x, int y) const {
  assert(x >= 0 && x < width && y >= 0 && y < height);
  const std::uint8_t* p = &rgba[offset(x, y)];
  return Rgba{p[0], p[1], p[2], p[3]};
}

void Image::set_pixel(int x, int y, Rgba colour) {
  assert(x >= 0 && x < width && y >= 0 && y < height);
  std::uint8_t* p = &rgba[offset(x, y)];
  p[0] = colour.r;
  p[1] = colour.g;
  p[2] = colour.b;
  p[3] = colour.a;
}

bool Image::is_opaque() const {
  for (std::size_t i = 3; i < rgba.size(); i += kChannels) {
    if (rgba[i] != 255) return false;
  }
  return true;
}

std::uint64_t Image::hash() const {
  std::uint64_t value = kFnvOffsetBasis;
  value = fnv1a_u32(value, static_cast<std::uint32_t>(width));
  value = fnv1a_u32(value, static_cast<std::uint32_t>(height));
  for (std::uint8_t byte : rgba) value = fnv1a_byte(value, byte);
  return value;
}

Image make_image(int width, int height, Rgba fill) {
  if (width < 0 || height < 0) {
    throw ImageError("make_image: size " + std::to_string(width) + "x" + std::to_string(height) +
                     " is negative");
  }
  Image image;
  image.resize(width, height);
  for (std::size_t i = 0; i < image.rgba.size(); i += kChannels) {
    image.rgba[i + 0] = fill.r;
    image.rgba[i + 1] = fill.g;
    image.rgba[i + 2] = fill.b;
    image.rgba[i + 3] = fill.a;
  }
  return image;
}

}  // namespace impulse2d::image

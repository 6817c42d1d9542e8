/// @file image.cpp
#include "golden/image.h"

#include "golden/error.h"
#include "golden/file_io.h"
#include "golden/png_codec.h"

#include <cassert>

namespace impulse2d::golden {

namespace {

constexpr std::uint64_t kFnvOffsetBasis = 0xcbf29ce484222325ull;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ull;

std::uint64_t fnv1a_byte(std::uint64_t hash, std::uint8_t byte) {
  return (hash ^ byte) * kFnvPrime;
}

std::uint64_t fnv1a_u32(std::uint64_t hash, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) {
    hash = fnv1a_byte(hash, static_cast<std::uint8_t>(value >> shift));
  }
  return hash;
}

}  // namespace

Image make_image(int width, int height, Rgba fill) {
  if (width < 0 || height < 0) {
    throw GoldenError("make_image: size " + std::to_string(width) + "x" +
                      std::to_string(height) + " is negative");
  }
  Image image;
  image.width = width;
  image.height = height;
  image.pixels.resize(image.pixel_count() * kChannels);
  for (std::size_t i = 0; i < image.pixels.size(); i += kChannels) {
    image.pixels[i + 0] = fill.r;
    image.pixels[i + 1] = fill.g;
    image.pixels[i + 2] = fill.b;
    image.pixels[i + 3] = fill.a;
  }
  return image;
}

void set_pixel(Image& image, int x, int y, Rgba colour) {
  assert(x >= 0 && x < image.width && y >= 0 && y < image.height);
  std::uint8_t* pixel = &image.pixels[image.offset(x, y)];
  pixel[0] = colour.r;
  pixel[1] = colour.g;
  pixel[2] = colour.b;
  pixel[3] = colour.a;
}

Rgba get_pixel(const Image& image, int x, int y) {
  assert(x >= 0 && x < image.width && y >= 0 && y < image.height);
  const std::uint8_t* pixel = &image.pixels[image.offset(x, y)];
  return Rgba{pixel[0], pixel[1], pixel[2], pixel[3]};
}

std::uint64_t rgba_hash(const Image& image) {
  std::uint64_t hash = kFnvOffsetBasis;
  hash = fnv1a_u32(hash, static_cast<std::uint32_t>(image.width));
  hash = fnv1a_u32(hash, static_cast<std::uint32_t>(image.height));
  for (std::uint8_t byte : image.pixels) hash = fnv1a_byte(hash, byte);
  return hash;
}

Image load_png(const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = read_file_bytes(file);
  Image image;
  std::string reason;
  if (!decode_png_bytes(bytes, image, reason)) {
    throw GoldenError("cannot decode PNG '" + file.string() + "': " + reason);
  }
  image.text = read_png_text(bytes);
  return image;
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != image.pixel_count() * kChannels) {
    throw GoldenError("encode_png: image " + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + " with " +
                      std::to_string(image.pixels.size()) + " bytes is not a valid RGBA image");
  }
  const std::vector<std::uint8_t> bytes = encode_png_bytes(image);
  if (bytes.empty()) throw GoldenError("encode_png: the PNG encoder failed");
  return image.text.empty() ? bytes : with_png_text(bytes, image.text);
}

void save_png(const std::filesystem::path& file, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_file_atomically(file, bytes.data(), bytes.size());
}

}  // namespace impulse2d::golden

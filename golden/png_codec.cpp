/// @file png_codec.cpp
/// stb_image / stb_image_write, compiled here with static linkage and wrapped.

#include "golden/png_codec.h"

#include "golden/image.h"
#include "golden/png_check.h"

#include <zlib.h>

#include <cstdlib>
#include <cstring>

namespace {

/// stb_image_write's compression hook: zlib at its best level gives smaller goldens than
/// stb's own deflate. Returns a malloc'd buffer (stb frees it with STBIW_FREE) or null.
unsigned char* zlib_compress(unsigned char* data, int data_length, int* out_length, int) {
  uLongf capacity = compressBound(static_cast<uLong>(data_length));
  auto* buffer = static_cast<unsigned char*>(std::malloc(capacity));
  if (buffer == nullptr) return nullptr;
  if (compress2(buffer, &capacity, data, static_cast<uLong>(data_length), Z_BEST_COMPRESSION) !=
      Z_OK) {
    std::free(buffer);
    return nullptr;
  }
  *out_length = static_cast<int>(capacity);
  return buffer;
}

}  // namespace

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS zlib_compress
#include <stb_image_write.h>

namespace impulse2d::golden {

bool decode_png_bytes(const std::vector<std::uint8_t>& bytes, Image& image, std::string& error) {
  error = png_structure_problem(bytes);
  if (!error.empty()) return false;
  int width = 0;
  int height = 0;
  int channels_in_file = 0;
  stbi_uc* data = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                        &height, &channels_in_file, kChannels);
  if (data == nullptr) {
    const char* reason = stbi_failure_reason();
    error = reason != nullptr ? reason : "unknown decoder error";
    return false;
  }
  image.width = width;
  image.height = height;
  image.pixels.assign(data, data + image.pixel_count() * kChannels);
  stbi_image_free(data);
  return true;
}

std::vector<std::uint8_t> encode_png_bytes(const Image& image) {
  std::vector<std::uint8_t> bytes;
  auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    const auto* begin = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), begin, begin + size);
  };
  if (stbi_write_png_to_func(append, &bytes, image.width, image.height, kChannels,
                             image.pixels.data(), image.width * kChannels) == 0) {
    bytes.clear();
  }
  return bytes;
}

}  // namespace impulse2d::golden

/// @file png.cpp
/// stb_image and stb_image_write, compiled here with static linkage (the only copy in the
/// project), with libdeflate as stb's zlib compressor and chunk checksum.

#include "image/png.h"

#include "image/error.h"
#include "image/file_io.h"
#include "image/png_check.h"

#include <libdeflate.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

namespace {

/// The libdeflate level of the encode running on this thread (stb's compression hook has no
/// context argument; the hook runs synchronously inside the encode call).
thread_local int t_deflate_level = 1;

struct CompressorDeleter {
  void operator()(libdeflate_compressor* compressor) const { libdeflate_free_compressor(compressor); }
};

/// stb's STBIW_ZLIB_COMPRESS hook: zlib-wrapped deflate of `data` in a malloc'd buffer that
/// stb frees with STBIW_FREE (free), or null. One compressor per thread and level: they are
/// not thread-safe.
unsigned char* libdeflate_zlib(unsigned char* data, int data_length, int* out_length, int) {
  thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter> fast(
      libdeflate_alloc_compressor(1));
  thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter> small(
      libdeflate_alloc_compressor(12));
  libdeflate_compressor* compressor = t_deflate_level >= 12 ? small.get() : fast.get();
  if (compressor == nullptr) return nullptr;
  const std::size_t length = static_cast<std::size_t>(data_length);
  const std::size_t capacity = libdeflate_zlib_compress_bound(compressor, length);
  auto* out = static_cast<unsigned char*>(std::malloc(capacity));
  if (out == nullptr) return nullptr;
  const std::size_t written = libdeflate_zlib_compress(compressor, data, length, out, capacity);
  if (written == 0) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(written);
  return out;
}

/// stb's STBIW_CRC32 hook: the CRC-32 of a chunk (libdeflate's, many times faster than stb's
/// byte-at-a-time table on the large IDAT chunk of a frame; the same value).
unsigned int libdeflate_chunk_crc(unsigned char* buffer, int length) {
  return libdeflate_crc32(0, buffer, static_cast<std::size_t>(length));
}

}  // namespace

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS libdeflate_zlib
#define STBIW_CRC32 libdeflate_chunk_crc
#include <stb_image_write.h>

namespace impulse2d::image {

namespace {

/// PNG row filter for every row (stb numbering: 0 none). Measured on a 1000-body 800x600 frame
/// with every overlay at libdeflate level 1: none 7.2 ms / 264 KB, sub 10.9 / 336, up
/// 11.3 / 337, average 11.9 / 380, Paeth 15.3 / 341, stb's per-row search 22.5 / 340.
constexpr int kRowFilter = 0;

/// Channels a PNG row holds when every pixel is opaque: the alpha bytes are left out. Measured
/// on the 151 frames of `ball_pit` at 800x600, libdeflate level 1: RGB takes 1.0-1.5 ms less a
/// frame than RGBA with every overlay (about 10 against 11 ms) and the same with shapes only;
/// the files are 4 % smaller with every overlay and 6 % larger with shapes only.
constexpr int kOpaqueChannels = 3;

/// The rows of `image` without their alpha bytes, packed three bytes a pixel, in `rgb` (its
/// size is three bytes a pixel and one more), when every pixel's alpha is 255; false, with
/// `rgb` unspecified, after the first row with an alpha below 255. The test is
/// `Image::is_opaque`'s, made in the same pass as the packing so the frame is read once.
bool opaque_rgb(const Image& image, std::vector<std::uint8_t>& rgb) {
  const std::size_t pixels = image.pixel_count();
  rgb.resize(pixels * kOpaqueChannels + 1);
  const std::uint8_t* source = image.rgba.data();
  std::uint8_t* target = rgb.data();
  const std::size_t row_pixels = static_cast<std::size_t>(image.width);
  for (std::size_t row_start = 0; row_start < pixels; row_start += row_pixels) {
    unsigned alpha = 255;
    for (std::size_t pixel = row_start; pixel < row_start + row_pixels; ++pixel) {
      // Four bytes copied, three kept: the fourth is overwritten by the next pixel's red (the
      // last pixel's lands in the spare byte).
      std::memcpy(target + pixel * kOpaqueChannels, source + pixel * kChannels, 4);
      alpha &= source[pixel * kChannels + 3];
    }
    if (alpha != 255) return false;
  }
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image, PngCompression compression) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != image.stride() * static_cast<std::size_t>(image.height)) {
    throw ImageError("encode_png: image " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " with " + std::to_string(image.rgba.size()) +
                     " bytes is not a valid RGBA image");
  }
  // stb keeps the filter in a file-level variable; it is set once, before any encode reads it.
  static const bool configured = [] {
    stbi_write_force_png_filter = kRowFilter;
    return true;
  }();
  (void)configured;
  t_deflate_level = compression == PngCompression::Small ? 12 : 1;
  thread_local std::vector<std::uint8_t> rgb;
  const bool opaque = opaque_rgb(image, rgb);
  const int channels = opaque ? kOpaqueChannels : kChannels;
  int length = 0;
  unsigned char* encoded = stbi_write_png_to_mem(opaque ? rgb.data() : image.rgba.data(),
                                                 image.width * channels, image.width, image.height,
                                                 channels, &length);
  if (encoded == nullptr) {
    throw ImageError("encode_png: the encoder failed on a " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " image (out of memory?)");
  }
  std::vector<std::uint8_t> bytes(encoded, encoded + length);
  STBIW_FREE(encoded);
  return image.text.empty() ? bytes : with_png_text(bytes, image.text);
}

Image decode_png(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& source) {
  const std::string problem = png_structure_problem(bytes);
  if (!problem.empty()) {
    throw ImageError("cannot decode PNG '" + source.string() + "': " + problem);
  }
  int width = 0;
  int height = 0;
  int channels_in_file = 0;
  stbi_uc* data = stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width,
                                        &height, &channels_in_file, kChannels);
  if (data == nullptr) {
    const char* reason = stbi_failure_reason();
    throw ImageError("cannot decode PNG '" + source.string() +
                     "': " + (reason != nullptr ? reason : "unknown decoder error"));
  }
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(data, data + image.pixel_count() * kChannels);
  stbi_image_free(data);
  image.text = read_png_text(bytes);
  return image;
}

Image load_png(const std::filesystem::path& file) { return decode_png(read_file_bytes(file), file); }

void save_png(const std::filesystem::path& file, const Image& image, PngCompression compression) {
  write_file_atomically(file, encode_png(image, compression));
}

}  // namespace impulse2d::image

/// @file stb_png_default.cpp
/// stb_image_write exactly as shipped: its own deflate (quality 8) and per-row filter search.
#include "render/stb_png.h"

#include <cstdlib>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

namespace impulse2d::render::detail {

bool stb_png_default(const std::uint8_t* rgba, int width, int height, std::vector<std::uint8_t>& png) {
  int length = 0;
  unsigned char* bytes = stbi_write_png_to_mem(rgba, width * 4, width, height, 4, &length);
  if (bytes == nullptr) return false;
  png.assign(bytes, bytes + length);
  STBIW_FREE(bytes);
  return true;
}

}  // namespace impulse2d::render::detail

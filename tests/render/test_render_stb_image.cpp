// stb_image's implementation for the renderer tests (compiled with warnings off: it is
// third-party code), behind `decode_png`.
#include "tests/support/test_render_support.h"

#include <cstring>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

namespace impulse2d::render::testing {

bool decode_png(const std::vector<std::uint8_t>& png, Frame& frame) {
  int width = 0;
  int height = 0;
  int channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &width, &height,
                                          &channels, 4);
  if (pixels == nullptr) return false;
  frame.resize(width, height);
  std::memcpy(frame.rgba.data(), pixels, frame.rgba.size());
  stbi_image_free(pixels);
  return true;
}

}  // namespace impulse2d::render::testing

/// @file driver_quirks.cpp
#include "render/driver_quirks.h"

namespace impulse2d::render {

bool point_sprites_safe(const std::string& gl_renderer) {
  const bool llvmpipe = gl_renderer.rfind("llvmpipe", 0) == 0;
  return !(llvmpipe && gl_renderer.find(", 128 bits)") != std::string::npos);
}

}  // namespace impulse2d::render

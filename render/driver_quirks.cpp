/// @file driver_quirks.cpp
#include "render/driver_quirks.h"

#include "render/render_error.h"

#include <cstdlib>

namespace impulse2d::render {

void check_driver(const std::string& gl_renderer) {
  const bool llvmpipe = gl_renderer.rfind("llvmpipe", 0) == 0;
  if (!llvmpipe || gl_renderer.find(", 128 bits)") == std::string::npos) return;
  const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
  const std::string cause = width != nullptr ? std::string("LP_NATIVE_VECTOR_WIDTH=") + width + " is set"
                                             : std::string("this CPU gives llvmpipe 128-bit vectors");
  throw RenderError("the renderer " + gl_renderer + " cannot draw these frames: " + cause +
                    ", and llvmpipe at 128-bit vectors corrupts the heap drawing text and discs "
                    "with this renderer's shader (the process would abort with a double free); "
                    "unset LP_NATIVE_VECTOR_WIDTH or set it to 256");
}

}  // namespace impulse2d::render

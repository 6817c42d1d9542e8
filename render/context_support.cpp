/// @file context_support.cpp
#include "render/context_support.h"

#include "render/gl_api.h"
#include "render/render_error.h"

#include <cstring>

namespace impulse2d::render::context_support {

namespace {

// Largest size accepted before a context exists; the driver's own limit is checked after.
constexpr int kMaxSize = 16384;

}  // namespace

std::string describe_request(const std::string& backend, int width, int height) {
  return backend + ", OpenGL " + std::to_string(requested_major) + "." +
         std::to_string(requested_minor) + " core profile, " + std::to_string(width) + "x" +
         std::to_string(height) + " RGBA8";
}

void check_size(const std::string& request, int width, int height) {
  if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize) {
    throw RenderError("cannot create offscreen context (" + request + "): size must be 1.." +
                      std::to_string(kMaxSize) + " pixels each way");
  }
}

void check_viewport_limit(const std::string& request, const std::string& renderer, int width,
                          int height) {
  GLint viewport_limits[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport_limits);
  if (width > viewport_limits[0] || height > viewport_limits[1]) {
    throw RenderError("cannot create offscreen context (" + request + "): " + renderer +
                      " draws at most " + std::to_string(viewport_limits[0]) + "x" +
                      std::to_string(viewport_limits[1]) + " pixels");
  }
}

void copy_bottom_up(const std::uint8_t* rows, int width, int height, Frame& frame) {
  frame.resize(width, height);
  const std::size_t stride = frame.stride();
  for (int row = 0; row < height; ++row) {
    const std::uint8_t* source = rows + static_cast<std::size_t>(height - 1 - row) * stride;
    std::memcpy(frame.rgba.data() + static_cast<std::size_t>(row) * stride, source, stride);
  }
}

}  // namespace impulse2d::render::context_support

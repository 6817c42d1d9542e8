/// @file osmesa_context.cpp
#include "render/osmesa_context.h"

#include "render/gl_api.h"
#include "render/render_error.h"

#include <GL/osmesa.h>

#include <cstdlib>
#include <cstring>

namespace impulse2d::render {

namespace {

constexpr int kRequestedMajor = 3;
constexpr int kRequestedMinor = 3;
// Largest size accepted before a context exists; the driver's own limit is checked after.
constexpr int kMaxSize = 16384;

// The gallium driver OSMesa will pick, for error messages.
std::string driver_name() {
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver != nullptr && driver[0] != '\0') return std::string("GALLIUM_DRIVER=") + driver;
  return "llvmpipe (default gallium driver)";
}

std::string describe_request(int width, int height) {
  return "OSMesa with " + driver_name() + ", OpenGL " + std::to_string(kRequestedMajor) + "." +
         std::to_string(kRequestedMinor) + " core profile, " + std::to_string(width) + "x" +
         std::to_string(height) + " RGBA8";
}

std::string gl_string(GLenum name) {
  const GLubyte* text = glGetString(name);
  return text != nullptr ? std::string(reinterpret_cast<const char*>(text)) : std::string("?");
}

}  // namespace

OsmesaContext::OsmesaContext(int width, int height) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > kMaxSize || height > kMaxSize) {
    throw RenderError("cannot create offscreen context (" + describe_request(width, height) +
                      "): size must be 1.." + std::to_string(kMaxSize) + " pixels each way");
  }
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            kRequestedMajor,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            kRequestedMinor,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw RenderError("cannot create offscreen context (" + describe_request(width, height) +
                      "): OSMesaCreateContextAttribs returned null; the driver may not support "
                      "that GL version (softpipe and llvmpipe do)");
  }
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  make_current();
  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);
  GLint viewport_limits[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport_limits);
  if (width > viewport_limits[0] || height > viewport_limits[1]) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
    throw RenderError("cannot create offscreen context (" + describe_request(width, height) +
                      "): " + renderer_ + " draws at most " + std::to_string(viewport_limits[0]) +
                      "x" + std::to_string(viewport_limits[1]) + " pixels");
  }
}

OsmesaContext::~OsmesaContext() {
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

void OsmesaContext::make_current() {
  if (OSMesaGetCurrentContext() == context_) return;
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
    throw RenderError("OSMesaMakeCurrent failed for the " + std::to_string(width_) + "x" +
                      std::to_string(height_) + " context (" + driver_name() + ")");
  }
}

void OsmesaContext::read_pixels(Frame& frame) {
  make_current();
  glFinish();  // OSMesa copies the finished image into buffer_, bottom row first
  frame.resize(width_, height_);
  const std::size_t stride = frame.stride();
  for (int row = 0; row < height_; ++row) {
    const std::uint8_t* source = buffer_.data() + static_cast<std::size_t>(height_ - 1 - row) * stride;
    std::memcpy(frame.rgba.data() + static_cast<std::size_t>(row) * stride, source, stride);
  }
}

std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height) {
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace impulse2d::render

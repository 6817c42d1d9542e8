/// @file osmesa_context.cpp
#include "render/osmesa_context.h"

#include "render/context_support.h"
#include "render/gl_api.h"
#include "render/render_error.h"

#include <GL/osmesa.h>

#include <cstdlib>

namespace impulse2d::render {

namespace {

// The gallium driver OSMesa will pick, for error messages.
std::string driver_name() {
  const char* driver = std::getenv("GALLIUM_DRIVER");
  if (driver != nullptr && driver[0] != '\0') return std::string("GALLIUM_DRIVER=") + driver;
  return "llvmpipe (default gallium driver)";
}

std::string describe_request(int width, int height) {
  return context_support::describe_request("OSMesa with " + driver_name(), width, height);
}

}  // namespace

OsmesaContext::OsmesaContext(int width, int height) : OffscreenContext(width, height) {
  context_support::check_size(describe_request(width, height), width, height);
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
                            context_support::requested_major,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            context_support::requested_minor,
                            0};
  context_ = OSMesaCreateContextAttribs(attributes, nullptr);
  if (context_ == nullptr) {
    throw RenderError("cannot create offscreen context (" + describe_request(width, height) +
                      "): OSMesaCreateContextAttribs returned null; the driver may not support "
                      "that GL version (softpipe and llvmpipe do)");
  }
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  make_current();
  read_gl_strings();
  try {
    context_support::check_viewport_limit(describe_request(width, height), renderer(), width,
                                          height);
  } catch (const RenderError&) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
    throw;
  }
}

OsmesaContext::~OsmesaContext() {
  if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(context_);
}

void OsmesaContext::make_current() {
  if (OSMesaGetCurrentContext() == context_) return;
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width(), height())) {
    throw RenderError("OSMesaMakeCurrent failed for the " + std::to_string(width()) + "x" +
                      std::to_string(height()) + " context (" + driver_name() + ")");
  }
}

void OsmesaContext::read_pixels(Frame& frame) {
  make_current();
  glFinish();  // OSMesa copies the finished image into buffer_, bottom row first
  context_support::copy_bottom_up(buffer_.data(), width(), height(), frame);
}

}  // namespace impulse2d::render

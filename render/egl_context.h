#pragma once
/// @file egl_context.h
/// The EGL backend of `OffscreenContext`: a display on Mesa's surfaceless platform
/// (EGL_MESA_platform_surfaceless; llvmpipe when the machine has no GPU, or with
/// LIBGL_ALWAYS_SOFTWARE=1), a GL context without a config or surface, drawing into a
/// framebuffer object. The backend that outlives OSMesa (removed in Mesa 25.1).

#include "render/offscreen_context.h"

#include <cstdint>
#include <vector>

namespace impulse2d::render {

/// An EGL surfaceless context asking for OpenGL 3.3 core, drawing into an RGBA8
/// renderbuffer of the given size, without depth.
class EglContext final : public OffscreenContext {
 public:
  /// Creates the display, the context and the framebuffer, and makes the context current.
  /// Throws `RenderError` naming the EGL step and error code that failed, or when
  /// width/height are out of range.
  EglContext(int width, int height);
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current() override;
  void read_pixels(Frame& frame) override;

 private:
  void release();
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  unsigned framebuffer_ = 0;
  unsigned renderbuffer_ = 0;
  std::vector<std::uint8_t> buffer_;  // glReadPixels' rows, bottom row first
};

}  // namespace impulse2d::render

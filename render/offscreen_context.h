#pragma once
/// @file offscreen_context.h
/// A GL 3.3 core context that draws into memory, behind a small interface with two
/// backends chosen at run time (offscreen_backend.h): OSMesa and EGL surfaceless.

#include "render/frame.h"

#include <memory>
#include <string>

namespace impulse2d::render {

/// An offscreen OpenGL context whose bound framebuffer has a fixed size in pixels.
/// A context is used from the thread that created it.
class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;
  /// Makes this context current on the calling thread. Throws `RenderError` on failure.
  virtual void make_current() = 0;
  /// Waits for all GL work, then copies the framebuffer into `frame` (resized to fit), rows
  /// top to bottom.
  virtual void read_pixels(Frame& frame) = 0;
  /// Framebuffer width, pixels.
  int width() const { return width_; }
  /// Framebuffer height, pixels.
  int height() const { return height_; }
  /// The GL_RENDERER string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
  const std::string& renderer() const { return renderer_; }
  /// The GL_VERSION string (e.g. "4.5 (Core Profile) Mesa 22.3.6").
  const std::string& version() const { return version_; }

 protected:
  /// A backend's context of width x height pixels.
  OffscreenContext(int width, int height) : width_(width), height_(height) {}
  /// Records GL_RENDERER and GL_VERSION of the backend's context, once it is current.
  void read_gl_strings();

 private:
  int width_ = 0;
  int height_ = 0;
  std::string renderer_;
  std::string version_;
};

/// A context of width x height pixels on the default backend (`default_backend()`), asking
/// for OpenGL 3.3 core, made current on the calling thread. Throws `RenderError` naming the
/// backend, the driver and the GL version requested when it cannot be created, or when the
/// size is not 1..limit.
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height);

}  // namespace impulse2d::render

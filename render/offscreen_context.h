#pragma once
/// @file offscreen_context.h
/// A GL 3.3 core context that draws into memory, behind a small interface so that the
/// OSMesa backend (removed from Mesa in 25.1) can be replaced by EGL-surfaceless later.

#include "render/frame.h"

#include <memory>
#include <string>

namespace impulse2d::render {

/// An offscreen OpenGL context with a default framebuffer of a fixed size in pixels.
/// A context is used from the thread that created it.
class OffscreenContext {
 public:
  virtual ~OffscreenContext() = default;
  /// Makes this context current on the calling thread. Throws `RenderError` on failure.
  virtual void make_current() = 0;
  /// Framebuffer width, pixels.
  virtual int width() const = 0;
  /// Framebuffer height, pixels.
  virtual int height() const = 0;
  /// Waits for all GL work, then copies the framebuffer into `frame` (resized to fit), rows
  /// top to bottom.
  virtual void read_pixels(Frame& frame) = 0;
  /// The GL_RENDERER string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
  virtual std::string renderer() const = 0;
  /// The GL_VERSION string (e.g. "4.5 (Core Profile) Mesa 22.3.6").
  virtual std::string version() const = 0;
};

/// The default backend: an OSMesa context of width x height pixels asking for OpenGL 3.3
/// core, made current on the calling thread. Throws `RenderError` naming the driver and the
/// GL version requested when it cannot be created, or when the size is not 1..limit.
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height);

}  // namespace impulse2d::render

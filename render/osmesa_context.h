#pragma once
/// @file osmesa_context.h
/// The OSMesa backend of `OffscreenContext`: Mesa's gallium driver (llvmpipe by default,
/// `GALLIUM_DRIVER=softpipe` for the reference rasteriser) drawing into a user buffer.

#include "render/offscreen_context.h"

#include <cstdint>
#include <vector>

struct osmesa_context;

namespace impulse2d::render {

/// An OSMesa context asking for OpenGL 3.3 core, with an RGBA8 colour buffer and no depth.
class OsmesaContext final : public OffscreenContext {
 public:
  /// Creates the context and makes it current. Throws `RenderError` naming the driver and
  /// the GL version asked for when OSMesa refuses, or when width/height are out of range.
  OsmesaContext(int width, int height);
  ~OsmesaContext() override;
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  void make_current() override;
  void read_pixels(Frame& frame) override;

 private:
  osmesa_context* context_ = nullptr;
  std::vector<std::uint8_t> buffer_;  // OSMesa's colour buffer, bottom row first
};

}  // namespace impulse2d::render

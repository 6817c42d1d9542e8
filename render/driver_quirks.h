#pragma once
/// @file driver_quirks.h
/// Driver bugs the renderer works around, each detected from the context's GL_RENDERER.

#include <string>

namespace impulse2d::render {

/// False when point sprites corrupt the heap in this driver: Mesa 22.3's llvmpipe running
/// 128-bit vectors (GL_RENDERER "llvmpipe (LLVM 15.0.6, 128 bits)", e.g. under
/// `LP_NATIVE_VECTOR_WIDTH=128`) aborts in malloc ("double free or corruption") on the first
/// frame that draws a point sprite (`GL_POINTS` with `gl_PointSize`); triangles are fine.
/// Quads give the same pixels, so the renderer then draws every primitive as a quad.
bool point_sprites_safe(const std::string& gl_renderer);

}  // namespace impulse2d::render

#pragma once
/// @file driver_quirks.h
/// Drivers the renderer cannot run on, detected from the context's GL_RENDERER before the
/// first frame, so a run stops with a message instead of aborting inside the driver.

#include <string>

namespace impulse2d::render {

/// Throws `RenderError` naming the cause and the fix when `gl_renderer` is a driver this
/// renderer crashes: Mesa 22.3's llvmpipe running 128-bit vectors (GL_RENDERER
/// "llvmpipe (LLVM 15.0.6, 128 bits)", e.g. under `LP_NATIVE_VECTOR_WIDTH=128`) corrupts the
/// heap while drawing text and discs with this renderer's shader (glibc then aborts with
/// "double free or corruption" or "malloc(): corrupted top size"); a minimal OSMesa program
/// does not crash. Any other renderer passes.
void check_driver(const std::string& gl_renderer);

}  // namespace impulse2d::render

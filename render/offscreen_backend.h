#pragma once
/// @file offscreen_backend.h
/// Which offscreen GL backend draws the frames, chosen at run time: OSMesa (Mesa up to 25.0)
/// or EGL on Mesa's surfaceless platform (EGL_MESA_platform_surfaceless). Both give llvmpipe
/// on a machine without a GPU, and the same pixels.

#include <memory>
#include <string>

namespace impulse2d::render {

class OffscreenContext;

/// An offscreen context implementation.
enum class Backend {
  OSMesa,  ///< libOSMesa drawing into a user buffer (removed from Mesa in 25.1)
  Egl,     ///< EGL surfaceless display, a GL context drawing into a framebuffer object
};

/// "osmesa" or "egl".
const char* backend_name(Backend backend);

/// Parses "osmesa" or "egl". Throws `RenderError` naming `where` (an option or variable) and
/// the value otherwise.
Backend parse_backend(const std::string& name, const std::string& where);

/// True when this build has `backend`: EGL always; OSMesa unless impulse2d was configured
/// with IMPULSE2D_OSMESA=OFF (for Mesa 25.1 and later, which has no OSMesa).
bool backend_available(Backend backend);

/// The backend used when none is named: the one given to `set_default_backend`, else the
/// environment variable IMPULSE2D_BACKEND ("osmesa" or "egl"; throws `RenderError` for
/// anything else), else OSMesa when this build has it, else EGL.
Backend default_backend();

/// Makes `backend` the default of this process (the command line's `--backend`).
void set_default_backend(Backend backend);

/// A context of width x height pixels on `backend`, asking for OpenGL 3.3 core, made current
/// on the calling thread. Throws `RenderError` naming the backend, the driver and the GL
/// version requested when it cannot be created, when the size is not 1..limit, or when this
/// build lacks the backend.
std::unique_ptr<OffscreenContext> create_offscreen_context(int width, int height, Backend backend);

}  // namespace impulse2d::render

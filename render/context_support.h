#pragma once
/// @file context_support.h
/// What the offscreen backends share (internal to render/): the GL version asked for, the
/// size checks before and after a context exists, and the bottom-up read-back.

#include "render/frame.h"

#include <cstdint>
#include <string>

namespace impulse2d::render::context_support {

/// OpenGL major version every backend asks for (core profile).
constexpr int requested_major = 3;
/// OpenGL minor version every backend asks for.
constexpr int requested_minor = 3;

/// "<backend>, OpenGL 3.3 core profile, WxH RGBA8": what was asked for, for error messages.
std::string describe_request(const std::string& backend, int width, int height);

/// Throws `RenderError` ("cannot create offscreen context (<request>): ...") unless width
/// and height are 1..16384, checked before any context exists.
void check_size(const std::string& request, int width, int height);

/// Throws `RenderError` naming `renderer` and its limit when the current context cannot draw
/// width x height pixels (GL_MAX_VIEWPORT_DIMS).
void check_viewport_limit(const std::string& request, const std::string& renderer, int width,
                          int height);

/// Copies width x height RGBA rows stored bottom row first into `frame` (resized), top row
/// first.
void copy_bottom_up(const std::uint8_t* rows, int width, int height, Frame& frame);

}  // namespace impulse2d::render::context_support

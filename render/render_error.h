#pragma once
/// @file render_error.h
/// The exception type of the renderer: context creation, shaders, bad sizes, file output.

#include "core/error.h"

namespace impulse2d::render {

/// Thrown when the renderer cannot do what it was asked. The message names the thing that
/// failed (driver, shader, file path, argument) and the reason.
class RenderError : public Error {
 public:
  /// An error carrying a complete, human-readable message.
  using Error::Error;
};

}  // namespace impulse2d::render

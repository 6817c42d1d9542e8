#pragma once
/// @file render_error.h
/// The exception type of the renderer: context creation, shaders, bad sizes, file output.

#include <stdexcept>
#include <string>

namespace impulse2d::render {

/// Thrown when the renderer cannot do what it was asked. The message names the thing that
/// failed (driver, shader, file path, argument) and the reason.
class RenderError : public std::runtime_error {
 public:
  /// An error carrying a complete, human-readable message.
  explicit RenderError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace impulse2d::render

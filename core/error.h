#pragma once
/// @file error.h
/// The exception type the core throws on API misuse, and the base of the one error type of
/// each layer above it (`render::RenderError`, `demos::UsageError` for scene files and
/// command lines), so a program can catch everything impulse2d throws as `impulse2d::Error`.

#include <stdexcept>
#include <string>

namespace impulse2d {

/// Thrown when the core is used wrongly: invalid shapes, stale handles, non-finite input.
/// The message names the function, the argument and the reason.
class Error : public std::runtime_error {
 public:
  /// Creates an error with a message that says what was wrong and where.
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace impulse2d

#pragma once
/// @file error.h
/// The single exception type the golden-image library throws.

#include <stdexcept>
#include <string>

namespace impulse2d::golden {

/// Thrown for unreadable or invalid inputs (PNG files, sidecars, tolerance objects,
/// environment variables) and failed writes. The message names the file or variable, the
/// field where there is one, and the reason.
class GoldenError : public std::runtime_error {
 public:
  /// Creates an error with a message that says what was wrong and where.
  explicit GoldenError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace impulse2d::golden

#pragma once
/// @file error.h
/// The exception the image library throws.

#include <stdexcept>
#include <string>

namespace impulse2d::image {

/// Thrown for unreadable or invalid images and files (PNG files, text chunks, sizes) and for
/// failed writes. The message names the file where there is one, and the reason.
class ImageError : public std::runtime_error {
 public:
  /// Creates an error with a message that says what was wrong and where.
  explicit ImageError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace impulse2d::image

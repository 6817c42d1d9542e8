#pragma once
/// @file usage_error.h
/// The error a user can fix by changing what they asked for: an unknown scene, a bad
/// parameter, an invalid scene file, a frame range outside the run. The command line exits
/// with status 2 for it and 1 for every other failure.

#include <stdexcept>
#include <string>

namespace impulse2d::demos {

/// Bad input from the user (command line or scene file). The message is complete: it names
/// the file, the field or option, and the reason.
class UsageError : public std::runtime_error {
 public:
  /// An error carrying a complete, human-readable message.
  explicit UsageError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace impulse2d::demos

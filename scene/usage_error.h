#pragma once
/// @file usage_error.h
/// The error a user can fix by changing what they asked for: an invalid scene file, a bad
/// parameter, an unknown scene, a frame range outside the run. The command line exits with
/// status 2 for it and 1 for every other failure.

#include "core/error.h"

namespace impulse2d::demos {

/// Bad input from the user (scene file or command line). The message is complete: it names
/// the file, the field or option, and the reason.
class UsageError : public Error {
 public:
  /// An error carrying a complete, human-readable message.
  using Error::Error;
};

}  // namespace impulse2d::demos

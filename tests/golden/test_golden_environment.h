#pragma once
/// @file test_golden_environment.h
/// Environment variables set for one test and restored afterwards, for the suites that test
/// GOLDEN_UPDATE, CI, GOLDEN_ARTIFACT_DIR and GOLDEN_IMAGES_DIR.

#include <cstdlib>
#include <map>
#include <optional>
#include <string>

namespace impulse2d::golden::testing {

/// Sets environment variables for one test and puts the previous values back afterwards.
class ScopedEnvironment {
 public:
  ScopedEnvironment() = default;
  ~ScopedEnvironment() {
    for (const auto& [name, value] : saved_) {
      if (value) {
        ::setenv(name.c_str(), value->c_str(), 1);
      } else {
        ::unsetenv(name.c_str());
      }
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;
  /// Sets `name` to `value`, or unsets it when `value` is null.
  void set(const std::string& name, const char* value) {
    if (saved_.count(name) == 0) {
      const char* previous = std::getenv(name.c_str());
      saved_[name] = previous ? std::optional<std::string>(previous) : std::nullopt;
    }
    if (value) {
      ::setenv(name.c_str(), value, 1);
    } else {
      ::unsetenv(name.c_str());
    }
  }

 private:
  std::map<std::string, std::optional<std::string>> saved_;
};

}  // namespace impulse2d::golden::testing

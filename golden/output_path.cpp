/// @file output_path.cpp
#include "golden/output_path.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "golden/error.h"

namespace impulse2d::golden {

namespace fs = std::filesystem;

void check_output_path(const fs::path& path, const std::string& option, bool folder) {
  auto fail = [&](const std::string& reason) {
    throw GoldenError(option + " " + path.string() + ": " + reason);
  };
  if (path.empty()) fail("empty path");
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::exists(status)) {
    if (folder && !fs::is_directory(status)) fail("exists and is not a folder");
    if (!folder && fs::is_directory(status)) fail("is a folder, expected a file");
    if (!folder && ::access(path.c_str(), W_OK) != 0) fail(std::strerror(errno));
  }
  fs::path ancestor = fs::absolute(path, error).parent_path();
  while (!fs::exists(fs::status(ancestor, error)) && ancestor.has_relative_path()) {
    ancestor = ancestor.parent_path();
  }
  if (!fs::is_directory(ancestor, error)) fail("'" + ancestor.string() + "' is not a folder");
  if (::access(ancestor.c_str(), W_OK | X_OK) != 0) {
    fail("cannot write in '" + ancestor.string() + "': " + std::strerror(errno));
  }
}

}  // namespace impulse2d::golden

/// @file output_folder.cpp
#include "frames/output_folder.h"

#include <unistd.h>

#include <stdexcept>
#include <system_error>

namespace impulse2d::demos {

void check_output_folder(const std::filesystem::path& folder, const std::string& where) {
  const std::filesystem::path wanted = folder.empty() ? std::filesystem::path(".") : folder;
  std::error_code error;
  std::filesystem::path existing = wanted;
  while (!std::filesystem::exists(existing, error)) {
    const std::filesystem::path parent = existing.has_parent_path() && existing.parent_path() != existing
                                             ? existing.parent_path()
                                             : std::filesystem::path(".");
    if (parent == existing) break;
    existing = parent;
  }
  const std::string prefix = where + ": ";
  if (!std::filesystem::is_directory(existing, error)) {
    throw std::runtime_error(prefix + "cannot use " + existing.string() +
                             " as a folder: it is not a folder");
  }
  if (::access(existing.c_str(), W_OK | X_OK) != 0) {
    throw std::runtime_error(prefix + "cannot write into the folder " + existing.string() +
                             ": permission denied");
  }
}

}  // namespace impulse2d::demos

/// @file output_guard.cpp
#include "frames/output_guard.h"

namespace impulse2d::demos {

OutputGuard::~OutputGuard() {
  if (committed_) return;
  std::error_code ignored;
  // remove_all: a "file" may be a directory moved into place whole.
  for (const std::filesystem::path& file : new_files_) std::filesystem::remove_all(file, ignored);
  // Innermost first; remove() leaves a directory that is not empty alone.
  for (auto it = new_directories_.rbegin(); it != new_directories_.rend(); ++it) {
    std::filesystem::remove(*it, ignored);
  }
}

void OutputGuard::will_create_directory(const std::filesystem::path& directory) {
  std::vector<std::filesystem::path> missing;
  std::error_code error;
  for (std::filesystem::path each = std::filesystem::absolute(directory, error).lexically_normal();
       !each.empty() && !std::filesystem::exists(each, error); each = each.parent_path()) {
    missing.push_back(each);
    if (each == each.parent_path()) break;
  }
  new_directories_.insert(new_directories_.end(), missing.rbegin(), missing.rend());
}

void OutputGuard::will_write_file(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::exists(file, error)) new_files_.push_back(file);
}

}  // namespace impulse2d::demos

#pragma once
/// @file output_guard.h
/// All-or-nothing output: remembers the files and directories a job creates and, unless the
/// job commits, removes them again. Nothing that existed before is touched.

#include <filesystem>
#include <vector>

namespace impulse2d::demos {

/// Removes what a failed job created.
class OutputGuard {
 public:
  OutputGuard() = default;
  /// Removes the created files, then the created directories that are empty, unless committed.
  ~OutputGuard();
  OutputGuard(const OutputGuard&) = delete;
  OutputGuard& operator=(const OutputGuard&) = delete;

  /// Call before creating `directory` (and its missing parents): the missing ones are removed
  /// on failure when empty.
  void will_create_directory(const std::filesystem::path& directory);
  /// Call before writing `file` (or moving a directory into place as `file`): it is removed
  /// (with its contents) on failure unless it existed before.
  void will_write_file(const std::filesystem::path& file);
  /// The directories this job will remove on failure (outermost first).
  const std::vector<std::filesystem::path>& new_directories() const { return new_directories_; }
  /// The job succeeded: keep everything.
  void commit() { committed_ = true; }

 private:
  std::vector<std::filesystem::path> new_files_;
  std::vector<std::filesystem::path> new_directories_;  // outermost first
  bool committed_ = false;
};

}  // namespace impulse2d::demos

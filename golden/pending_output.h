#pragma once
/// @file pending_output.h
/// Output a run prepares beside its place under a hidden name and moves into place only when
/// the whole run has succeeded (`commit`); destroyed uncommitted (a failure, a signal), it
/// is removed and whatever was there before stays as it was.

#include <filesystem>
#include <string>

namespace impulse2d::golden {

/// One file: written as `<folder>/.<name>.pending-<pid>`, renamed over `<folder>/<name>`.
class PendingFile {
 public:
  /// Writes `text` under the hidden name. Throws `GoldenError` naming the file and the
  /// system's reason when the write fails (nothing is left then).
  PendingFile(std::filesystem::path file, const std::string& text);
  /// Removes the hidden file unless committed.
  ~PendingFile();
  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  /// Renames the hidden file over the file. Throws `GoldenError` when the rename fails.
  void commit();

 private:
  std::filesystem::path file_;
  std::filesystem::path pending_;
  bool committed_ = false;
};

/// One directory: built as `<parent>/.<name>.staging-<pid>`, swapped into place in one step
/// (`swap_directory_into_place`), the old directory removed after.
class PendingDirectory {
 public:
  /// Creates the (empty) staging directory. Throws `GoldenError` when it cannot.
  explicit PendingDirectory(std::filesystem::path target);
  /// Removes the staging directory and its contents unless committed.
  ~PendingDirectory();
  PendingDirectory(const PendingDirectory&) = delete;
  PendingDirectory& operator=(const PendingDirectory&) = delete;

  /// Where to build the directory's contents.
  const std::filesystem::path& path() const { return staging_; }
  /// `path` in `path()` as it will be named once committed (under the target).
  std::filesystem::path final_path(const std::filesystem::path& path) const;
  /// Moves the staging directory into place and removes the directory it replaced.
  /// Throws `GoldenError` when the move fails (then nothing changed).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace impulse2d::golden

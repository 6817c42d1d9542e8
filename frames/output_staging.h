#pragma once
/// @file output_staging.h
/// A run's files are written into a hidden staging directory inside the output directory
/// and moved into place only when the run has succeeded; a failed or interrupted run removes
/// the staging directory with everything in it, so nothing half-written ever appears.

#include <filesystem>
#include <string>
#include <vector>

#include "frames/output_guard.h"

namespace impulse2d::demos {

/// `directory/.impulse2d-staging-<tag>-<pid>`, removed (with its contents) on destruction.
class StagingDirectory {
 public:
  /// Removes staging directories of `tag` left in `directory` by processes that no longer run
  /// (a SIGKILLed run), then creates this process's. Throws `std::runtime_error` naming the
  /// directory when it cannot be created.
  StagingDirectory(const std::filesystem::path& directory, const std::string& tag);
  /// Removes the staging directory and whatever is still in it.
  ~StagingDirectory();
  StagingDirectory(const StagingDirectory&) = delete;
  StagingDirectory& operator=(const StagingDirectory&) = delete;

  /// Where to write.
  const std::filesystem::path& path() const { return path_; }
  /// Moves every file in the staging directory into the output directory, in name order,
  /// telling `guard` about each first (so a failure half-way removes the ones already
  /// moved that did not exist before). Returns the files' new paths.
  std::vector<std::filesystem::path> publish(OutputGuard& guard);

 private:
  std::filesystem::path directory_;
  std::filesystem::path path_;
};

/// The files `directory/<scene>_<digits>.png` (frames of `scene` from any run), in name order.
std::vector<std::filesystem::path> existing_frames(const std::filesystem::path& directory,
                                                   const std::string& scene);

}  // namespace impulse2d::demos

/// @file output_staging.cpp
#include "frames/output_staging.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>

namespace impulse2d::demos {
namespace {

namespace fs = std::filesystem;

std::string staging_prefix(const std::string& tag) { return ".impulse2d-staging-" + tag + "-"; }

/// True when `name` is `prefix` followed by the id of a process that no longer exists.
bool is_stale(const std::string& name, const std::string& prefix) {
  if (name.compare(0, prefix.size(), prefix) != 0) return false;
  const std::string digits = name.substr(prefix.size());
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(),
                                     [](char c) { return c >= '0' && c <= '9'; })) {
    return false;
  }
  const long pid = std::strtol(digits.c_str(), nullptr, 10);
  return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

}  // namespace

StagingDirectory::StagingDirectory(const fs::path& directory, const std::string& tag)
    : directory_(directory) {
  const std::string prefix = staging_prefix(tag);
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    if (is_stale(entry.path().filename().string(), prefix)) fs::remove_all(entry.path(), error);
  }
  path_ = directory / (prefix + std::to_string(static_cast<long>(::getpid())));
  fs::remove_all(path_, error);
  if (!fs::create_directory(path_, error)) {
    throw std::runtime_error("cannot create the staging directory " + path_.string() + ": " +
                             error.message());
  }
}

StagingDirectory::~StagingDirectory() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
}

std::vector<fs::path> StagingDirectory::publish(OutputGuard& guard) {
  std::vector<fs::path> staged;
  for (const fs::directory_entry& entry : fs::directory_iterator(path_)) {
    staged.push_back(entry.path());
  }
  std::sort(staged.begin(), staged.end());
  std::vector<fs::path> published;
  for (const fs::path& file : staged) {
    const fs::path target = directory_ / file.filename();
    guard.will_write_file(target);
    std::error_code error;
    fs::rename(file, target, error);
    if (error) {
      throw std::runtime_error("cannot move " + file.string() + " to " + target.string() + ": " +
                               error.message());
    }
    published.push_back(target);
  }
  return published;
}

std::vector<fs::path> existing_frames(const fs::path& directory, const std::string& scene) {
  std::vector<fs::path> frames;
  std::error_code error;
  const std::string prefix = scene + "_";
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - 4, 4, ".png") != 0) {
      continue;
    }
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    if (std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      frames.push_back(entry.path());
    }
  }
  std::sort(frames.begin(), frames.end());
  return frames;
}

}  // namespace impulse2d::demos

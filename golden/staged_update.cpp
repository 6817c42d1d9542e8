/// @file staged_update.cpp
#include "golden/staged_update.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "golden/directory_swap.h"
#include "golden/error.h"
#include "image/file_io.h"

namespace impulse2d::golden {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

/// The journal's name in the staging folder.
constexpr const char* kJournal = "journal.json";

/// The inode of `path` (its identity across renames), or nothing when it does not exist.
std::optional<std::uint64_t> inode_of(const fs::path& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0) return std::nullopt;
  return static_cast<std::uint64_t>(status.st_ino);
}

/// Opens and exclusively locks `folder` without waiting; -1 when another process holds it.
int try_lock(const fs::path& folder) {
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) {
    throw GoldenError("cannot open '" + folder.string() + "': " + std::strerror(errno));
  }
  if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
    ::close(descriptor);
    return -1;
  }
  return descriptor;
}

/// Moves each scene folder of the journal that is not yet in place into place.
void roll_forward(const fs::path& golden_dir, const fs::path& staging) {
  json journal;
  try {
    journal = json::parse(image::read_text_file(staging / kJournal));
  } catch (const json::exception& error) {
    throw GoldenError("'" + (staging / kJournal).string() + "': not a journal: " + error.what());
  }
  for (const json& entry : journal.at("scenes")) {
    const std::string name = entry.at("name").get<std::string>();
    const std::uint64_t inode = entry.at("inode").get<std::uint64_t>();
    if (inode_of(golden_dir / name) == inode) continue;
    if (inode_of(staging / name) == inode) swap_directory_into_place(staging / name, golden_dir / name);
  }
}

/// Adds to `staged` (a scene folder as it will be) every file of `golden` (the scene folder
/// as it is) that it lacks, as hard links (copies where links fail).
void complete_scene_folder(const fs::path& golden, const fs::path& staged) {
  std::error_code error;
  if (!fs::is_directory(golden, error)) return;
  for (auto it = fs::recursive_directory_iterator(golden); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path target = staged / it->path().lexically_relative(golden);
    if (fs::exists(fs::symlink_status(target))) continue;
    if (it->is_symlink()) {
      fs::copy_symlink(it->path(), target);
    } else if (it->is_directory()) {
      fs::create_directories(target);
    } else {
      fs::create_hard_link(it->path(), target, error);
      if (error) fs::copy_file(it->path(), target);
    }
  }
}

}  // namespace

Recovery recover_interrupted_update(const fs::path& golden_dir) {
  const fs::path staging = golden_dir / kStagingFolderName;
  std::error_code error;
  if (!fs::is_directory(staging, error)) return Recovery::None;
  const int lock = try_lock(staging);
  if (lock < 0) return Recovery::Busy;
  const bool forward = fs::exists(staging / kJournal);
  try {
    if (forward) roll_forward(golden_dir, staging);
    fs::remove_all(staging);
  } catch (...) {
    ::close(lock);
    throw;
  }
  ::close(lock);
  return forward ? Recovery::RolledForward : Recovery::RolledBack;
}

std::string describe_interrupted_update(const fs::path& golden_dir) {
  const fs::path staging = golden_dir / kStagingFolderName;
  std::error_code error;
  if (!fs::is_directory(staging, error)) return "";
  return "an interrupted update's staging folder " + staging.string() +
         (fs::exists(staging / kJournal)
              ? " (its commit had begun: it would be finished)"
              : " (it had not begun its commit: it would be removed, the goldens stay)");
}

StagedUpdate::StagedUpdate(fs::path golden_dir)
    : golden_dir_(std::move(golden_dir)), staging_(golden_dir_ / kStagingFolderName) {
  if (recover_interrupted_update(golden_dir_) == Recovery::Busy) {
    throw GoldenError("another 'golden update' is writing '" + golden_dir_.string() +
                      "' (its staging folder " + staging_.string() +
                      " is locked); wait for it to finish");
  }
  std::error_code error;
  for (fs::path missing = golden_dir_; !missing.empty() && !fs::exists(missing, error);
       missing = missing.parent_path()) {
    created_.push_back(missing);
  }
  fs::create_directories(golden_dir_, error);
  if (error || !fs::create_directory(staging_, error) || error) {
    throw GoldenError("cannot create the staging folder '" + staging_.string() + "': " +
                      (error ? error.message() : "it exists (another update?)"));
  }
  lock_ = try_lock(staging_);
  if (lock_ < 0) {
    throw GoldenError("another 'golden update' took '" + staging_.string() + "'");
  }
}

StagedUpdate::~StagedUpdate() {
  std::error_code ignored;
  if (!committed_) {
    fs::remove_all(staging_, ignored);
    for (const fs::path& folder : created_) fs::remove(folder, ignored);  // only when empty
  }
  ::close(lock_);
}

std::size_t StagedUpdate::commit(const std::function<void(const std::string&)>& after_swap) {
  std::error_code ignored;
  fs::remove_all(scratch(), ignored);
  std::vector<std::string> scenes;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && name.front() != '.') scenes.push_back(name);
  }
  std::sort(scenes.begin(), scenes.end());
  json journal = {{"scenes", json::array()}};
  for (const std::string& scene : scenes) {
    try {
      complete_scene_folder(golden_dir_ / scene, staging_ / scene);
    } catch (const fs::filesystem_error& error) {
      throw GoldenError("cannot prepare '" + (staging_ / scene).string() + "': " + error.what());
    }
    journal["scenes"].push_back({{"name", scene}, {"inode", *inode_of(staging_ / scene)}});
  }
  image::write_text_file_atomically(staging_ / kJournal, journal.dump(2) + "\n");

  // (scene, where its old folder went: empty when there was none)
  std::vector<std::pair<std::string, fs::path>> swapped;
  try {
    for (const std::string& scene : scenes) {
      swapped.emplace_back(scene, swap_directory_into_place(staging_ / scene, golden_dir_ / scene));
      if (after_swap) after_swap(scene);
    }
  } catch (...) {
    for (auto it = swapped.rbegin(); it != swapped.rend(); ++it) {
      const fs::path target = golden_dir_ / it->first;
      if (it->second.empty()) {
        fs::rename(target, staging_ / it->first, ignored);
      } else {
        swap_directory_into_place(it->second, target);
      }
    }
    fs::remove(staging_ / kJournal, ignored);
    throw;
  }
  committed_ = true;
  fs::remove_all(staging_, ignored);
  return scenes.size();
}

}  // namespace impulse2d::golden

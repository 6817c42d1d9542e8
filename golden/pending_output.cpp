/// @file pending_output.cpp
#include "golden/pending_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "golden/directory_swap.h"
#include "golden/error.h"
#include "image/file_io.h"

namespace impulse2d::golden {

namespace fs = std::filesystem;

namespace {

/// `<folder of path>/.<name of path><suffix>-<pid>`.
fs::path hidden_sibling(const fs::path& path, const std::string& suffix) {
  const fs::path name = path.filename().empty() ? path.parent_path().filename() : path.filename();
  const fs::path folder = path.filename().empty() ? path.parent_path().parent_path() : path.parent_path();
  return folder / ("." + name.string() + suffix + "-" + std::to_string(::getpid()));
}

}  // namespace

PendingFile::PendingFile(fs::path file, const std::string& text)
    : file_(std::move(file)), pending_(hidden_sibling(file_, ".pending")) {
  try {
    image::write_text_file_atomically(pending_, text);
  } catch (const GoldenError& error) {
    throw GoldenError("cannot write '" + file_.string() + "': " + error.what());
  }
}

PendingFile::~PendingFile() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove(pending_, ignored);
}

void PendingFile::commit() {
  if (std::rename(pending_.c_str(), file_.c_str()) != 0) {
    throw GoldenError("cannot write '" + file_.string() + "': renaming '" + pending_.string() +
                      "' failed: " + std::strerror(errno));
  }
  committed_ = true;
}

PendingDirectory::PendingDirectory(fs::path target)
    : target_(std::move(target)), staging_(hidden_sibling(target_, ".staging")) {
  std::error_code error;
  fs::remove_all(staging_, error);
  fs::create_directories(staging_, error);
  if (error) {
    throw GoldenError("cannot create '" + staging_.string() + "' (to prepare '" +
                      target_.string() + "'): " + error.message());
  }
}

PendingDirectory::~PendingDirectory() {
  if (committed_) return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

fs::path PendingDirectory::final_path(const fs::path& path) const {
  const fs::path relative = path.lexically_relative(staging_);
  if (relative.empty() || *relative.begin() == "..") return path;
  return relative == "." ? target_ : target_ / relative;
}

void PendingDirectory::commit() {
  const fs::path old = swap_directory_into_place(staging_, target_);
  committed_ = true;
  std::error_code ignored;
  if (!old.empty()) fs::remove_all(old, ignored);
}

}  // namespace impulse2d::golden

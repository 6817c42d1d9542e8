/// @file directory_swap.cpp
#include "golden/directory_swap.h"

#include <fcntl.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "golden/error.h"

namespace impulse2d::golden {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& from, const fs::path& to, int reason) {
  throw GoldenError("cannot move '" + from.string() + "' to '" + to.string() +
                    "': " + std::strerror(reason));
}

}  // namespace

fs::path swap_directory_into_place(const fs::path& staged, const fs::path& target) {
  std::error_code error;
  if (!fs::exists(fs::symlink_status(target, error))) {
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), error);
    if (std::rename(staged.c_str(), target.c_str()) != 0) fail(staged, target, errno);
    return {};
  }
  if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    return staged;
  }
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) fail(staged, target, errno);
  fs::path old = staged;
  old += ".old";
  if (std::rename(target.c_str(), old.c_str()) != 0) fail(target, old, errno);
  if (std::rename(staged.c_str(), target.c_str()) != 0) {
    const int reason = errno;
    std::rename(old.c_str(), target.c_str());  // put the old one back
    fail(staged, target, reason);
  }
  return old;
}

}  // namespace impulse2d::golden

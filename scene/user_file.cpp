/// @file user_file.cpp
#include "scene/user_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  explicit FileDescriptor(int descriptor) : value(descriptor) {}
  ~FileDescriptor() {
    if (value >= 0) ::close(value);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int value;
};

std::string too_large(const std::string& path, const UserFileKind& kind, std::uintmax_t bytes,
                      bool at_least) {
  return path + ": the " + kind.name + " has " + (at_least ? "more than " : "") +
         std::to_string(bytes) + " bytes; the limit is " + std::to_string(kind.max_bytes) + " (" +
         kind.limit_in_words + ")";
}

}  // namespace

std::string read_user_file(const std::string& path, const UserFileKind& kind) {
  // O_NONBLOCK: opening a FIFO for reading must not wait for a writer.
  const FileDescriptor file(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (file.value < 0) {
    const int reason = errno;
    if (reason == ENOENT || reason == ENOTDIR) {
      throw UsageError(path + ": cannot open the " + kind.name + " (does it exist?)");
    }
    if (reason == EACCES || reason == EPERM) {
      throw UsageError(path + ": cannot open the " + kind.name + " (permission denied?)");
    }
    throw UsageError(path + ": cannot open the " + kind.name + ": " + std::strerror(reason));
  }
  struct stat status {};
  if (::fstat(file.value, &status) != 0) {
    throw UsageError(path + ": cannot read the " + kind.name + ": " + std::strerror(errno));
  }
  if (!S_ISREG(status.st_mode)) {
    throw UsageError(path + ": not a regular file (a " + kind.name + " must be " + kind.expected +
                     ")");
  }
  if (static_cast<std::uintmax_t>(status.st_size) > kind.max_bytes) {
    throw UsageError(too_large(path, kind, static_cast<std::uintmax_t>(status.st_size), false));
  }
  // Read to the end, but never past the limit (the file may grow while it is read).
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t got = ::read(file.value, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw UsageError(path + ": cannot read the " + kind.name + ": " + std::strerror(errno));
    if (got == 0) break;
    text.append(buffer, static_cast<std::size_t>(got));
    if (text.size() > kind.max_bytes) throw UsageError(too_large(path, kind, kind.max_bytes, true));
  }
  return text;
}

}  // namespace impulse2d::demos

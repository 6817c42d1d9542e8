#pragma once
/// @file user_file.h
/// Reading a file the user names (a scene file, a lab scenario, a shard CSV): only a regular
/// file under a size limit is read. A FIFO, a device (/dev/zero), a socket or a directory is
/// refused without waiting on it or reading it, so a bad path fails at once with a message
/// instead of blocking or filling memory.

#include <cstdint>
#include <string>

namespace impulse2d::demos {

/// What kind of file a reader expects, for its messages and its limit.
struct UserFileKind {
  const char* name;           ///< in messages: "scene file", "lab CSV"
  const char* expected;       ///< what a file of this kind is: "a plain .json file"
  std::uintmax_t max_bytes;   ///< the largest file accepted, bytes
  const char* limit_in_words; ///< `max_bytes` for people: "4 MiB"
};

/// The whole contents of `path`. Throws `UsageError` "<path>: <reason>" when it does not exist
/// ("cannot open the <name> (does it exist?)"), cannot be opened, is not a regular file ("not
/// a regular file (a <name> must be <expected>)"), is larger than `kind.max_bytes` ("the <name>
/// has N bytes; the limit is M (<limit_in_words>)") or cannot be read.
std::string read_user_file(const std::string& path, const UserFileKind& kind);

}  // namespace impulse2d::demos

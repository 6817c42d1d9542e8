#pragma once
/// @file child_process.h
/// What the programs that impulse2d starts without a shell (ffmpeg for video, gnuplot for the
/// lab's charts) have in common: finding them on PATH, waiting for them, and saying how they
/// ended.

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>

namespace impulse2d::demos {

/// The executable `name` on PATH, or nothing.
std::optional<std::filesystem::path> find_on_path(const char* name);

/// Waits for `child`, through interruptions by a signal; its wait status, or -1 when it cannot
/// be waited for (errno says why).
int wait_for_child(pid_t child);

/// A wait status in words: "exit status 1", "killed by signal 9 (Killed)".
std::string describe_wait_status(int status);

}  // namespace impulse2d::demos

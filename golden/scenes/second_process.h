#pragma once
/// @file second_process.h
/// The second process of a golden check or update: `impulse2d golden frame` of the same
/// golden, run as a child, so a frame that depends on the process (addresses, the pid, the
/// clock) fails as *nondeterminism*. A signal to this process while it waits ends the child
/// too (SIGTERM, then SIGKILL after a grace period) and removes its files.

#include <filesystem>
#include <string>

#include "golden/check_run.h"
#include "golden/scenes/golden_catalog.h"

namespace impulse2d::golden {

/// Produces `spec`'s frame with `<executable> golden frame <scene file> <name> --out
/// <folder>/frame.png` in a child process; `folder` is created for the call and removed
/// after it, whatever happens. Throws `GoldenError` naming the golden and how the child
/// ended when it fails, and `demos::Interrupted` when SIGINT, SIGTERM or SIGHUP arrives
/// while it runs (the child is ended and waited for first).
FrameProducer other_process_producer(const std::string& executable, const GoldenSpec& spec,
                                     const std::filesystem::path& folder);

}  // namespace impulse2d::golden

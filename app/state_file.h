#pragma once
/// @file state_file.h
/// `--save-state` / `--load-state`: a run's world saved to a file and a run started from one.
///
/// Layout: 8 bytes "I2DSTATE", u32 layout version (1), u64 fingerprint of the scene (the
/// payload hash of its world's snapshot at step 0: scene file, parameters and settings), u32
/// scene-name length and the name (for messages), then the core snapshot (`core/snapshot.h`,
/// which carries its own version and hash). Every number little-endian.

#include <string>

#include "scene/scene_run.h"

namespace impulse2d::demos {

/// The fingerprint of a run that has not stepped yet: the scene as built with its parameters.
std::uint64_t scene_fingerprint(const SceneRun& fresh_run);

/// Writes `run`'s world to `file` atomically (a failed write leaves the old file). `fingerprint`
/// is `scene_fingerprint` of the run before it stepped. Throws `UsageError` naming the file.
void save_state_file(const std::string& file, const SceneRun& run, std::uint64_t fingerprint);

/// Continues the fresh `run` from `file`. Throws `UsageError` naming the file for a file that
/// cannot be read, is not a state file, is of another layout version, another scene (or other
/// parameters), or corrupt.
void load_state_file(const std::string& file, SceneRun& run);

}  // namespace impulse2d::demos

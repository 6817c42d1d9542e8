#pragma once
/// @file state_file.h
/// `--save-state` / `--load-state`: a run's world saved to a file and a run started from one.
///
/// Layout (version 2), every number little-endian:
///   8 bytes "I2DSTATE", u32 layout version (2),
///   u64 fingerprint of the scene (FNV-1a 64 over the payload hash of its world's snapshot at
///       step 0 and the parameters' summary: scene file, parameters and settings),
///   u32 scene-name length and the name (for messages),
///   u64 world byte count and the core snapshot (`core/snapshot.h`, which carries its own
///       version and hash),
///   u64 script byte count, u64 FNV-1a 64 hash of the script bytes, and the script's state
///       (`StepScript::save_state`: its own version, then its fields; none without a script).
/// The file ends there. Version 1 (no script section, so no scripted scene) is refused.

#include <string>

#include "scene/scene_run.h"

namespace impulse2d::demos {

/// The fingerprint of a run that has not stepped yet: the scene as built with its parameters.
std::uint64_t scene_fingerprint(const SceneRun& fresh_run);

/// Writes `run`'s world and its script's state to `file` atomically (a failed write leaves the
/// old file). `fingerprint` is `scene_fingerprint` of the run before it stepped. Throws
/// `UsageError` naming the file.
void save_state_file(const std::string& file, const SceneRun& run, std::uint64_t fingerprint);

/// Continues the fresh `run` from `file`. Throws `UsageError` naming the file for a file that
/// cannot be read, is not a state file, is of another layout version, another scene (or other
/// parameters), or corrupt (in its world or in its script's state); `run` then keeps its state.
void load_state_file(const std::string& file, SceneRun& run);

}  // namespace impulse2d::demos

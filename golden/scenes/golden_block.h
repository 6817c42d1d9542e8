#pragma once
/// @file golden_block.h
/// The `golden` block of a JSON scene file: which frames of the scene are goldens, at what
/// size, with which overlays and theme, held to which tolerance, and where the goldens live.
/// The scene loader ignores the block; `impulse2d golden` reads it here.
///
/// ```json
/// "golden": {
///   "dir": "goldens",                  (optional; relative to the scene file; default "goldens")
///   "size": [320, 240],                (optional; default 320x240)
///   "tolerance": {"threshold": 2, "max_diff_pixels": 20, "max_diff_ratio": 0.001,
///                 "masks": [[0, 0, 120, 14]]},                       (optional; strict)
///   "frames": [
///     {"name": "start", "step": 0},
///     {"name": "landed", "step": 120, "overlays": "normals,impulses", "theme": "dark"}
///   ]
/// }
/// ```
/// Goldens are `<dir>/<scene name>/<frame name>.png` with their sidecars.

#include <filesystem>
#include <string>
#include <vector>

#include "golden/tolerance.h"
#include "golden/scenes/golden_catalog.h"

namespace impulse2d::golden {

/// The goldens one scene file declares.
struct SceneGoldens {
  std::string scene_file;                ///< the file, as given
  std::filesystem::path golden_dir;      ///< where its goldens live (the block's "dir")
  std::vector<GoldenSpec> frames;        ///< one per golden frame, in the block's order
  Tolerance tolerance;                   ///< the block's tolerance (strict when absent)
};

/// Largest step a golden frame may have: each check simulates from step 0.
inline constexpr int kMaxGoldenStep = 100000;

/// Reads the scene file's `golden` block (the scene itself is validated by the scene
/// loader). Throws `GoldenError` "<file>: field 'golden.<path>': <reason>" for a file
/// without a block, unknown fields, a frame name that is not [A-Za-z0-9_-]+ or repeats, a
/// step outside 0..kMaxGoldenStep, an unknown overlay or theme, a size outside 16..2048, or
/// bad tolerance values; and `demos::UsageError` for an invalid scene.
SceneGoldens read_scene_goldens(const std::string& scene_file);

}  // namespace impulse2d::golden

#pragma once
/// @file golden_catalog.h
/// The golden images of the built-in scenes: which scene, which frame, which overlays. One
/// entry is one image in golden_images/<scene>/<name>.png and one test.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace impulse2d::golden {

/// Golden frames are this small so the set stays a few megabytes; the HUD stays legible.
inline constexpr int kGoldenWidth = 320;
/// Height of every golden frame, pixels.
inline constexpr int kGoldenHeight = 240;

/// One golden image of a built-in scene or of a JSON scene file.
struct GoldenSpec {
  std::string scene;      ///< scene name, e.g. "pyramid" (a file's "name", else its stem)
  std::string name;       ///< golden name within the scene, e.g. "settled_overlays"
  std::int64_t step = 0;  ///< steps simulated before the frame is drawn
  /// `DebugDrawFlag`s; 0 means the scene's own default overlays.
  std::uint32_t overlays = 0;
  /// Parameter overrides ("rows", "8"), applied over the scene's defaults.
  std::vector<std::pair<std::string, std::string>> params;
  /// The JSON scene file the scene comes from; empty for a built-in scene.
  std::string scene_file;
  bool dark_theme = false;     ///< draw with the dark theme instead of the light one
  int width = kGoldenWidth;    ///< frame width, pixels
  int height = kGoldenHeight;  ///< frame height, pixels
  /// Threads sharing each step of the run (`WorldSettings::worker_count`; the CLI's
  /// `--workers`): the frame and its state are the same for any count.
  int worker_count = 1;

  /// "<scene>/<name>": the golden's path below golden_images/ without extension.
  std::string id() const { return scene + "/" + name; }
};

/// Every golden of the suite, grouped by scene in registry order: for each built-in scene
/// the first frame, a frame in mid-motion and a settled (or final) frame with the scene's
/// default overlays, and mid-motion and settled frames with every overlay on.
const std::vector<GoldenSpec>& golden_catalog();

/// The catalog entry with id "<scene>/<name>", or nullptr.
const GoldenSpec* find_golden(const std::string& id);

/// "<scene>_<name>": the id as a GoogleTest parameter name (letters, digits, '_').
std::string golden_test_name(const GoldenSpec& spec);

}  // namespace impulse2d::golden

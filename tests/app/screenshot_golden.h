#pragma once
/// @file screenshot_golden.h
/// A browser screenshot against its committed golden: golden_images/<name>.png beside
/// <name>.json, which holds {"description": ..., "tolerance": {...} (tolerance.h's fields),
/// "tolerance_reason": ...}. Compared as the golden suite compares frames (exact RGBA hash
/// first, then the tolerance's rules); written only when GOLDEN_UPDATE asks for it and CI
/// is not set.

#include <filesystem>
#include <string>

#include "golden/check_run.h"

namespace impulse2d::testing {

/// The verdict of `check_screenshot`.
struct ScreenshotCheck {
  bool passed = false;          ///< exact or within tolerance, or the golden was written
  bool golden_written = false;  ///< the update mode wrote the screenshot as the golden
  std::string message;          ///< the comparison, the reason for the tolerance, artifacts
};

/// Compares `screenshot` with the golden `name` (e.g. "viewer/tutorial_frame3_normals") in
/// `settings.golden_dir` under the sidecar's tolerance. A failure leaves actual.png,
/// expected.png and diff.png in `settings.artifact_root`/<name>/ (when the root is set).
/// Throws `golden::GoldenError` when the sidecar is missing or malformed or a PNG cannot be
/// read or written.
ScreenshotCheck check_screenshot(const std::string& name, const std::filesystem::path& screenshot,
                                 const golden::CheckSettings& settings);

}  // namespace impulse2d::testing

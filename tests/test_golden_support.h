#pragma once
/// @file test_golden_support.h
/// What the golden suites share: where the goldens and artifacts are, and the settings a
/// check runs with.

#include <filesystem>

#include "tools/golden/check_run.h"

namespace impulse2d::golden::testing {

/// golden_images/ of the source tree (GOLDEN_IMAGES_DIR overrides it).
std::filesystem::path golden_dir();

/// The suite's settings: goldens, GOLDEN_ARTIFACT_DIR (default <build>/golden_artifacts),
/// update mode from GOLDEN_UPDATE and CI.
CheckSettings suite_settings();

}  // namespace impulse2d::golden::testing

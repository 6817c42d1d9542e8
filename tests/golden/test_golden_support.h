#pragma once
/// @file test_golden_support.h
/// What the golden suites share: where the goldens and artifacts are, and the settings a
/// check runs with.

#include <filesystem>

#include <string>

#include "golden/check_run.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden::testing {

/// golden_images/ of the source tree (GOLDEN_IMAGES_DIR overrides it).
std::filesystem::path golden_dir();

/// The suite's settings: goldens, GOLDEN_ARTIFACT_DIR (default <build>/golden_artifacts),
/// update mode from GOLDEN_UPDATE and CI.
CheckSettings suite_settings();

/// Checks the built-in golden `golden` (an id such as "tutorial/motion") against its scene run
/// with `change` applied, reading the goldens only: no update, no artifacts. Throws
/// `std::logic_error` for an unknown golden.
CheckOutcome check_golden_variant(const std::string& golden, const SceneVariant& change);

/// True when the check passed on this run's renderer: the frame matched its golden, or
/// another renderer without a baseline drew it and the physics matched (pixels unchecked).
/// What "unchanged" means on any renderer (llvmpipe with the committed goldens, softpipe
/// without baselines).
bool passes_on_this_renderer(const CheckOutcome& outcome);

}  // namespace impulse2d::golden::testing

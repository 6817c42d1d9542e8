#pragma once
/// @file artifacts.h
/// Everything about one failure in one directory: <root>/<scene>/<golden>/ holds
///   actual.png     this run's image            actual.json   its sidecar (for promotion)
///   expected.png   the golden, when it exists
///   diff.png       `diff_overlay`, when the sizes agree
///   heatmap.png    `diff_heatmap`, when the sizes agree
///   metrics.json   class, message, comparison metrics, tolerance, state hashes, renderers,
///                  the noise-envelope judgement (when there was one)

#include "golden/failure.h"
#include "image/image.h"
#include "golden/sidecar.h"

#include <filesystem>
#include <string>

namespace impulse2d::golden {

/// The artifact root: $GOLDEN_ARTIFACT_DIR when set and non-empty, else `fallback` (the
/// suite passes a directory under its build tree).
std::filesystem::path artifact_root_from_environment(const std::filesystem::path& fallback);

/// Writes a failure's artifacts into <root>/<check.name>/ (created; files replaced). Pass
/// null for `expected` when the golden is missing and for `actual_sidecar` when there is
/// nothing to promote. Returns that directory. Throws `GoldenError` when the name is not
/// a relative path without "..", or a write fails.
std::filesystem::path write_failure_artifacts(const std::filesystem::path& root,
                                              const GoldenCheck& check, const image::Image& actual,
                                              const image::Image* expected,
                                              const Sidecar* actual_sidecar);

}  // namespace impulse2d::golden

#pragma once
/// @file failure.h
/// Why a golden check failed, as one of a few classes, each with its own message. The class
/// comes from the physics state hashes and a repeat render before any pixel is blamed, so
/// a failure says *simulation diverged* or *rasterisation differs*, not just "pixels differ".

#include "tools/golden/body_drift.h"
#include "tools/golden/compare.h"
#include "tools/golden/sidecar.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The kinds of golden failure, most fundamental first.
enum class FailureClass {
  None,                  ///< the check passed
  Nondeterminism,        ///< two renders (or runs) of the same frame differ
  MissingGolden,         ///< no golden image for this name
  SizeMismatch,          ///< golden and actual sizes differ
  SimulationDiverged,    ///< the physics state hash differs from the sidecar's
  RasterisationDiffers,  ///< same physics state, pixels beyond tolerance
};

/// Everything known about one golden check; the caller fills what it measured.
struct GoldenCheck {
  std::string name;  ///< "<scene>/<golden>", e.g. "circles/start"
  /// True when the golden PNG (and its sidecar) exist.
  bool golden_present = true;
  /// The image comparison; absent when the golden is missing.
  std::optional<CompareResult> comparison;
  /// The golden sidecar's state hash; absent when the golden is missing.
  std::optional<std::uint64_t> expected_state_hash;
  /// This run's physics state hash at the frame.
  std::uint64_t actual_state_hash = 0;
  /// True when simulating and rendering the frame a second time gave the same state hash
  /// and the same RGBA hash. Nondeterminism is a failure of its own, never absorbed by
  /// tolerance.
  bool second_render_identical = true;
  /// The bodies that moved most relative to the golden run (see `largest_drifts`).
  std::vector<BodyDrift> moved_bodies;
  /// The renderer recorded in the golden's sidecar.
  RendererFingerprint expected_renderer;
  /// The renderer of this run.
  RendererFingerprint actual_renderer;
};

/// Classifies a check: Nondeterminism, then MissingGolden, SizeMismatch, SimulationDiverged
/// (state hashes differ, whatever the pixels say), RasterisationDiffers (same state, the
/// comparison failed), else None.
FailureClass classify_failure(const GoldenCheck& check);

/// Human name of a class, e.g. "simulation diverged".
std::string failure_class_name(FailureClass failure_class);

/// Identifier of a class for JSON, e.g. "simulation_diverged".
std::string failure_class_id(FailureClass failure_class);

/// The message for a check's class: names the golden, says what differs and by how much,
/// and what to do next (e.g. promote a missing golden).
std::string failure_message(const GoldenCheck& check);

}  // namespace impulse2d::golden

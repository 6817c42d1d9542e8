#pragma once
/// @file failure.h
/// Why a golden check failed, as one of a few classes, each with its own message. The class
/// comes from the physics state hashes and a repeat render before any pixel is blamed, so
/// a failure says *simulation diverged* or *rasterisation differs*, not just "pixels differ";
/// when the golden carries a noise envelope, a divergence is further told apart as
/// *numerical noise* or *behaviour changed*.

#include "golden/body_drift.h"
#include "golden/compare.h"
#include "golden/noise_envelope.h"
#include "golden/sidecar.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The kinds of golden failure, most fundamental first.
enum class FailureClass {
  None,                  ///< the check passed
  Nondeterminism,        ///< two renders of the same frame differ (in one or two processes)
  MissingGolden,         ///< no golden image for this name
  SizeMismatch,          ///< golden and actual sizes differ
  /// The physics state hash differs from the sidecar's, which has no noise envelope.
  SimulationDiverged,
  /// The state hash differs, but every body and quantity stayed inside the golden's noise
  /// envelope, and that envelope and the run's largest move are small against the scene
  /// (`kNoiseBoundFraction`): a rounding change (safe to promote after a look).
  NumericalNoise,
  /// The run stayed inside the envelope, but the envelope is large against the scene: its
  /// chaos amplifies rounding to the size of the change observed, so noise and a real change
  /// cannot be told apart at this frame (an earlier frame can). Never promoted on trust.
  CannotTell,
  /// The state hash differs and bodies or quantities left the golden's noise envelope: the
  /// physics behaves differently (a regression unless intended).
  BehaviourChanged,
  RasterisationDiffers,  ///< same physics state, pixels beyond tolerance
  /// Drawn by another renderer than the golden, with no baseline for it: the physics was
  /// checked and matches, the pixels could not be. Not a failure.
  NoRendererBaseline,
  /// As NoRendererBaseline, but the run requires pixels (`--require-pixels`,
  /// IMPULSE2D_REQUIRE_PIXELS=1): a failure, so a CI image whose renderer changed does not
  /// stop checking pixels unnoticed.
  RendererBaselineRequired,
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
  /// True unless the frame was also produced in another process (`CheckSettings::repeat`,
  /// or before a golden is written) and that gave a different state hash or RGBA hash: a
  /// value that depends on the process (an address under ASLR, the pid, the clock).
  bool other_process_identical = true;
  /// The judgement against the golden's noise envelope; present when the state hashes
  /// differ and the golden's sidecar has an envelope.
  std::optional<NoiseVerdict> noise;
  /// The bodies that moved most relative to the golden run (see `largest_drifts`).
  std::vector<BodyDrift> moved_bodies;
  /// True when this run's renderer differs from the golden's and no baseline for it exists:
  /// only the physics is checked.
  bool renderer_baseline_missing = false;
  /// True when the run requires pixels to be compared: a missing renderer baseline is then
  /// a failure (`RendererBaselineRequired`) instead of a skip.
  bool pixels_required = false;
  /// The renderer baseline this run's pixels would be compared with (or written to), relative
  /// to the golden directory; empty when the golden's own renderer drew the frame.
  std::string renderer_baseline;
  /// The renderer recorded in the golden's sidecar.
  RendererFingerprint expected_renderer;
  /// The renderer of this run.
  RendererFingerprint actual_renderer;
};

/// Classifies a check: Nondeterminism, then MissingGolden, SizeMismatch; when the state
/// hashes differ (whatever the pixels say) NumericalNoise, CannotTell or BehaviourChanged by
/// `noise`, or
/// SimulationDiverged without one; then NoRendererBaseline (RendererBaselineRequired when
/// `pixels_required`) when the pixels had nothing to be compared with; RasterisationDiffers (same state, the comparison failed), else None.
FailureClass classify_failure(const GoldenCheck& check);

/// Human name of a class, e.g. "simulation diverged".
std::string failure_class_name(FailureClass failure_class);

/// Identifier of a class for JSON, e.g. "simulation_diverged".
std::string failure_class_id(FailureClass failure_class);

/// The message for a check's class: names the golden, says what differs and by how much,
/// and what to do next (e.g. promote a missing golden).
std::string failure_message(const GoldenCheck& check);

}  // namespace impulse2d::golden

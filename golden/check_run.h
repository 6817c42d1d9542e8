#pragma once
/// @file check_run.h
/// One golden check from start to finish, for any source of frames: produce the frame,
/// compare it with golden_images/<name>.png under its sidecar's tolerance, on a mismatch
/// produce it again to rule out nondeterminism, classify, leave the artifacts and the HTML
/// report, and write the golden when the update mode says so.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "golden/body_drift.h"
#include "golden/failure.h"
#include "image/image.h"
#include "golden/sidecar.h"
#include "golden/update_mode.h"

namespace impulse2d::golden {

/// One production of a golden's frame: the pixels and the physics state behind them.
struct ProducedFrame {
  image::Image image;                   ///< the rendered frame
  std::uint64_t state_hash = 0;  ///< the world's state hash at that frame
  /// Every body's pose at that frame, named by creation order (and the scene file's names),
  /// for drift reports and the noise judgement.
  std::vector<BodyPose> bodies;
  /// The same poses named by world slot ("body 7 (generation 2)"), to judge a sidecar
  /// written before bodies were named by creation order (`is_slot_named`); may be empty.
  std::vector<BodyPose> slot_bodies;
  /// Whole-world quantities at `noise_checkpoint_steps(frame)`, judged against the golden's
  /// noise envelope when the state hash differs.
  std::vector<PhysicsSample> samples;
  RendererFingerprint renderer;  ///< what drew it
};

/// Simulates and renders a golden's frame from scratch. Called once per check, and a second
/// time only when the first result does not match the golden (or there is none).
using FrameProducer = std::function<ProducedFrame()>;

/// Measures the golden's noise envelope (reruns of its scene with rounding-sized
/// perturbations).
/// Called only when a sidecar is about to be written: a golden, or a failure's promotable
/// actual.json.
using NoiseMeasurer = std::function<NoiseEnvelope()>;

/// What a check needs besides the frame.
struct CheckSettings {
  std::filesystem::path golden_dir;  ///< the golden set, e.g. <source>/golden_images
  /// Where written goldens go, with `golden_dir`'s layout (a `StagedUpdate`'s folder, moved
  /// into place by its commit); empty: into `golden_dir` itself.
  std::filesystem::path write_dir;
  /// Where failures leave their artifacts and index.html; empty: write none.
  std::filesystem::path artifact_root;
  UpdateMode update_mode = UpdateMode::None;  ///< which goldens this run may write
  std::size_t drift_count = 5;                ///< how many moved bodies a divergence message names
  /// Processes each checked frame is produced in: 2 also produces it in another process and
  /// fails as nondeterministic when the two differ. Writing a golden always compares with a
  /// second process (when the caller can produce one), whatever this says.
  int repeat = 1;
  /// When set, the tolerance every check is held to (and that written sidecars carry),
  /// instead of each golden sidecar's: a scene file's golden block.
  std::optional<Tolerance> tolerance;
  /// When true, a frame drawn by a renderer without a baseline fails
  /// (`RendererBaselineRequired`) instead of being checked by its physics only.
  bool require_pixels = false;
};

/// The outcome of `run_golden_check`.
struct CheckOutcome {
  GoldenCheck check;                                ///< everything measured
  FailureClass failure_class = FailureClass::None;  ///< `classify_failure(check)`
  /// True when the update mode wrote the golden (then the check counts as passed).
  bool golden_written = false;
  /// The failure's artifact directory; empty when none was written.
  std::filesystem::path artifact_dir;
  /// The regenerated HTML report; empty when none was written.
  std::filesystem::path report;

  /// True when the frame matched its golden, the run wrote the golden on request, or only
  /// the physics could be checked (another renderer, no baseline for it) and matched.
  bool passed() const {
    return failure_class == FailureClass::None ||
           failure_class == FailureClass::NoRendererBaseline || golden_written;
  }
  /// `failure_message(check)`, then where the artifacts and report are; for passes, a line
  /// saying so (and that the golden was written, when it was).
  std::string message() const;
};

/// Settings from the environment: GOLDEN_IMAGES_DIR (else `golden_dir`), GOLDEN_ARTIFACT_DIR
/// (else `artifact_root`), the update mode from GOLDEN_UPDATE and CI
/// (`update_mode_from_environment`), `repeat` from GOLDEN_REPEAT (1 or 2; default 1) and
/// `require_pixels` from IMPULSE2D_REQUIRE_PIXELS (`require_pixels_from_environment`).
/// Throws `GoldenError` for a bad GOLDEN_UPDATE, GOLDEN_REPEAT or IMPULSE2D_REQUIRE_PIXELS.
CheckSettings check_settings_from_environment(const std::filesystem::path& golden_dir,
                                              const std::filesystem::path& artifact_root);

/// IMPULSE2D_REQUIRE_PIXELS: "1" true; unset, empty or "0" false. Throws `GoldenError` for
/// anything else.
bool require_pixels_from_environment();

/// The golden's PNG for `name` ("<scene>/<golden>") in `golden_dir`.
std::filesystem::path golden_png_path(const std::filesystem::path& golden_dir,
                                      const std::string& name);

/// Runs one check. The golden counts as present when both its PNG and its sidecar exist.
/// When this run's renderer is not the golden's, the pixels are compared with (and written
/// to) that renderer's baseline (`renderer_baseline_png`) and the physics with the golden's
/// sidecar; without a baseline the class is NoRendererBaseline when the physics matches,
/// and a write mode writes the baseline (never when the physics differs).
/// A failure writes `write_failure_artifacts` (the actual's sidecar carries the golden's
/// tolerance, or the strict default) and regenerates the report under the artifact root,
/// one process at a time (a lock file in the root); a pass removes a stale failure
/// directory of the same name. With `measure_noise`, every sidecar written carries the
/// noise envelope it measures. `produce_in_other_process` produces the same frame in a
/// separate process; it is called when `settings.repeat` is 2 and before any golden is
/// written, and a difference is *nondeterminism* (nothing written); the scene suites always
/// pass one. Throws `GoldenError` for unreadable
/// goldens or sidecars and failed writes, and whatever the callbacks throw.
CheckOutcome run_golden_check(const std::string& name, const std::string& scene, int frame,
                              const FrameProducer& produce, const CheckSettings& settings,
                              const NoiseMeasurer& measure_noise = nullptr,
                              const FrameProducer& produce_in_other_process = nullptr);

}  // namespace impulse2d::golden

/// @file check_run.cpp
#include "image/png.h"
#include "golden/check_run.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdlib>
#include <optional>

#include "golden/artifacts.h"
#include "golden/compare.h"
#include "golden/error.h"
#include "golden/renderer_baseline.h"
#include "golden/report.h"

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;

/// Holds an exclusive lock on <root>/.lock while alive, so test processes running in
/// parallel do not interleave writing artifacts and regenerating the report.
class RootLock {
 public:
  explicit RootLock(const fs::path& root) {
    fs::create_directories(root);
    const fs::path file = root / ".lock";
    descriptor_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor_ < 0 || ::flock(descriptor_, LOCK_EX) != 0) {
      if (descriptor_ >= 0) ::close(descriptor_);
      throw GoldenError("cannot lock '" + file.string() + "'");
    }
  }
  ~RootLock() {
    ::flock(descriptor_, LOCK_UN);
    ::close(descriptor_);
  }
  RootLock(const RootLock&) = delete;
  RootLock& operator=(const RootLock&) = delete;

 private:
  int descriptor_ = -1;
};

/// The sidecar that would make `frame` this check's golden.
Sidecar sidecar_for(const std::string& scene, int frame, const ProducedFrame& produced,
                    const Tolerance& tolerance) {
  Sidecar sidecar;
  sidecar.scene = scene;
  sidecar.frame = frame;
  sidecar.width = produced.image.width;
  sidecar.height = produced.image.height;
  sidecar.state_hash = produced.state_hash;
  sidecar.renderer = produced.renderer;
  sidecar.tolerance = tolerance;
  sidecar.bodies = produced.bodies;
  return sidecar;
}

/// True when two productions of a frame have the same state hash and the same pixels.
bool same_production(const ProducedFrame& a, const ProducedFrame& b) {
  return a.state_hash == b.state_hash && a.image.width == b.image.width &&
         a.image.height == b.image.height && a.image.hash() == b.image.hash();
}

/// True when the first production already settles the check as a pass.
bool matches(const GoldenCheck& check) { return classify_failure(check) == FailureClass::None; }

}  // namespace

std::string CheckOutcome::message() const {
  if (golden_written) {
    return "golden '" + check.name + "' written (" + failure_class_name(failure_class) +
           " before the update); review it with git diff before committing";
  }
  if (failure_class == FailureClass::None) return "golden '" + check.name + "' matches";
  std::string text = failure_message(check);
  if (!artifact_dir.empty()) text += "\n  artifacts: " + artifact_dir.string();
  if (!report.empty()) text += "\n  report: " + report.string();
  return text;
}

CheckSettings check_settings_from_environment(const fs::path& golden_dir,
                                              const fs::path& artifact_root) {
  CheckSettings settings;
  const char* golden_override = std::getenv("GOLDEN_IMAGES_DIR");
  settings.golden_dir = golden_override != nullptr && golden_override[0] != '\0'
                            ? fs::path(golden_override)
                            : golden_dir;
  settings.artifact_root = artifact_root_from_environment(artifact_root);
  settings.update_mode = update_mode_from_environment().mode;
  const char* repeat = std::getenv("GOLDEN_REPEAT");
  const std::string repeat_text = repeat != nullptr ? repeat : "";
  if (repeat_text == "2") {
    settings.repeat = 2;
  } else if (!repeat_text.empty() && repeat_text != "1") {
    throw GoldenError("GOLDEN_REPEAT='" + repeat_text +
                      "' is not supported; use 1 (one process) or 2 (also compare with a "
                      "second process)");
  }
  settings.require_pixels = require_pixels_from_environment();
  return settings;
}

bool require_pixels_from_environment() {
  const char* value = std::getenv("IMPULSE2D_REQUIRE_PIXELS");
  const std::string text = value != nullptr ? value : "";
  if (text.empty() || text == "0") return false;
  if (text == "1") return true;
  throw GoldenError("IMPULSE2D_REQUIRE_PIXELS='" + text +
                    "' is not supported; use 1 (a frame drawn by a renderer without a baseline "
                    "fails) or 0 (it is checked by its physics only)");
}

fs::path golden_png_path(const fs::path& golden_dir, const std::string& name) {
  return golden_dir / fs::path(name + ".png");
}

CheckOutcome run_golden_check(const std::string& name, const std::string& scene, int frame,
                              const FrameProducer& produce, const CheckSettings& settings,
                              const NoiseMeasurer& measure_noise,
                              const FrameProducer& produce_in_other_process) {
  const fs::path png = golden_png_path(settings.golden_dir, name);
  const fs::path sidecar_file = sidecar_path_for(png);

  CheckOutcome outcome;
  GoldenCheck& check = outcome.check;
  check.name = name;
  check.golden_present = fs::exists(png) && fs::exists(sidecar_file);
  check.pixels_required = settings.require_pixels;

  std::optional<image::Image> expected;
  std::optional<Sidecar> golden_sidecar;
  if (check.golden_present) {
    golden_sidecar = read_sidecar(sidecar_file, name + ".json");
    check.expected_state_hash = golden_sidecar->state_hash;
    check.expected_renderer = golden_sidecar->renderer;
  }

  const ProducedFrame actual = produce();
  check.actual_state_hash = actual.state_hash;
  check.actual_renderer = actual.renderer;

  // The pixels are compared with the golden's own, or with the baseline of this run's
  // renderer when another renderer made the golden; the physics always with the golden's.
  fs::path pixel_png = png;
  Tolerance tolerance = golden_sidecar ? golden_sidecar->tolerance : Tolerance{};
  const bool other_renderer = golden_sidecar && !golden_sidecar->renderer.gl_renderer.empty() &&
                              !actual.renderer.gl_renderer.empty() &&
                              golden_sidecar->renderer != actual.renderer;
  if (other_renderer) {
    pixel_png = renderer_baseline_png(settings.golden_dir, name, actual.renderer);
    check.renderer_baseline = pixel_png.lexically_relative(settings.golden_dir).generic_string();
    if (fs::exists(pixel_png) && fs::exists(sidecar_path_for(pixel_png))) {
      const Sidecar baseline =
          read_sidecar(sidecar_path_for(pixel_png), check.renderer_baseline);
      check.expected_renderer = baseline.renderer;
      tolerance = baseline.tolerance;
      expected = image::load_png(pixel_png);
    } else {
      check.renderer_baseline_missing = true;
    }
  } else if (check.golden_present) {
    expected = image::load_png(png);
  }
  if (settings.tolerance) tolerance = *settings.tolerance;
  if (expected) check.comparison = compare_images(*expected, actual.image, tolerance);

  if (!matches(check)) {
    check.second_render_identical = same_production(actual, produce());
    if (golden_sidecar && golden_sidecar->state_hash != actual.state_hash) {
      // A sidecar written before bodies were named by creation order is judged by slot.
      const std::vector<BodyPose>& actual_bodies =
          is_slot_named(golden_sidecar->bodies) && !actual.slot_bodies.empty() ? actual.slot_bodies
                                                                               : actual.bodies;
      check.moved_bodies =
          largest_drifts(golden_sidecar->bodies, actual_bodies, settings.drift_count);
      if (!golden_sidecar->noise.empty()) {
        check.noise = judge_against_envelope(golden_sidecar->noise, golden_sidecar->bodies,
                                             actual_bodies, actual.samples);
      }
    }
  }
  bool other_process_compared = false;
  auto compare_with_other_process = [&] {
    if (!produce_in_other_process || other_process_compared) return;
    other_process_compared = true;
    check.other_process_identical = same_production(actual, produce_in_other_process());
    outcome.failure_class = classify_failure(check);
  };
  outcome.failure_class = classify_failure(check);
  if (settings.repeat >= 2) compare_with_other_process();
  // Another renderer's baseline is written only when the physics is the golden's: the
  // golden's own sidecar stays the physics authority.
  auto may_write = [&] {
    return should_write_golden(settings.update_mode, outcome.failure_class) &&
           (!other_renderer || actual.state_hash == golden_sidecar->state_hash);
  };
  if (may_write()) compare_with_other_process();

  Sidecar actual_sidecar = sidecar_for(scene, frame, actual, tolerance);
  const bool write_golden = may_write();
  const bool promotable = outcome.failure_class != FailureClass::Nondeterminism;
  const bool write_artifacts = !settings.artifact_root.empty() &&
                               outcome.failure_class != FailureClass::None && !write_golden;
  if (measure_noise && !other_renderer && (write_golden || (write_artifacts && promotable))) {
    actual_sidecar.noise = measure_noise();
  }
  if (write_golden) {
    const fs::path written =
        settings.write_dir.empty()
            ? pixel_png
            : settings.write_dir / pixel_png.lexically_relative(settings.golden_dir);
    image::save_png(written, actual.image);
    write_sidecar(sidecar_path_for(written), actual_sidecar);
    outcome.golden_written = true;
  }

  if (settings.artifact_root.empty()) return outcome;
  // Another renderer's failure is filed under its baseline's name, so promoting it writes
  // that baseline and never the golden; with other physics it is not promotable at all.
  GoldenCheck artifact_check = check;
  if (other_renderer) {
    artifact_check.name = fs::path(check.renderer_baseline).replace_extension().generic_string();
  }
  const bool promote_sidecar =
      promotable && (!other_renderer || actual.state_hash == golden_sidecar->state_hash);
  const RootLock lock(settings.artifact_root);
  if (outcome.passed()) {
    // A failure of an earlier run must not linger in the report once the golden passes.
    const fs::path stale = settings.artifact_root / fs::path(artifact_check.name);
    if (fs::exists(stale / "metrics.json")) {
      fs::remove_all(stale);
      for (fs::path parent = stale.parent_path();
           parent != settings.artifact_root && fs::is_empty(parent);
           parent = parent.parent_path()) {
        fs::remove(parent);
      }
      write_html_report(settings.artifact_root);
    }
    return outcome;
  }
  outcome.artifact_dir = write_failure_artifacts(settings.artifact_root, artifact_check,
                                                 actual.image, expected ? &*expected : nullptr,
                                                 promote_sidecar ? &actual_sidecar : nullptr);
  write_html_report(settings.artifact_root);
  outcome.report = settings.artifact_root / "index.html";
  return outcome;
}

}  // namespace impulse2d::golden

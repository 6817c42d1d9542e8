/// @file failure.cpp
#include "golden/failure.h"

#include "image/hex_hash.h"

#include <iomanip>
#include <sstream>

namespace impulse2d::golden {

namespace {

/// How many envelope escapes a message names.
constexpr std::size_t kEscapesNamed = 3;

/// "Image: <comparison>", or why the pixels were not compared.
std::string image_text(const GoldenCheck& check) {
  if (check.renderer_baseline_missing || !check.comparison) {
    return "Image: not compared (no baseline for this renderer, " + check.renderer_baseline + ")";
  }
  return "Image: " + check.comparison->message();
}

/// A failure message's next line: the verdict first, then one line per part (physics,
/// bodies, image), indented under it.
constexpr const char* kNextLine = "\n  ";

/// "Renderer differs: golden drawn by X, this run by Y" on its own line when the
/// fingerprints differ.
std::string renderer_note(const GoldenCheck& check) {
  if (check.expected_renderer == check.actual_renderer) return "";
  return std::string(kNextLine) + "Renderer differs: golden drawn by '" + check.expected_renderer.describe() +
         "', this run by '" + check.actual_renderer.describe() + "'";
}

/// "physics state hash X, the golden's sidecar has Y".
std::string hashes(const GoldenCheck& check) {
  return "physics state hash " + image::to_hex_hash(check.actual_state_hash) +
         ", the golden's sidecar has " + image::to_hex_hash(*check.expected_state_hash);
}

}  // namespace

FailureClass classify_failure(const GoldenCheck& check) {
  if (!check.second_render_identical || !check.other_process_identical) {
    return FailureClass::Nondeterminism;
  }
  if (!check.golden_present) return FailureClass::MissingGolden;
  if (!check.renderer_baseline_missing) {
    if (!check.comparison) return FailureClass::MissingGolden;
    if (check.comparison->outcome == CompareOutcome::SizeMismatch) {
      return FailureClass::SizeMismatch;
    }
  }
  if (check.expected_state_hash && *check.expected_state_hash != check.actual_state_hash) {
    if (!check.noise) return FailureClass::SimulationDiverged;
    if (!check.noise->within()) return FailureClass::BehaviourChanged;
    return check.noise->cannot_tell() ? FailureClass::CannotTell : FailureClass::NumericalNoise;
  }
  if (check.renderer_baseline_missing) {
    return check.pixels_required ? FailureClass::RendererBaselineRequired
                                 : FailureClass::NoRendererBaseline;
  }
  if (!check.comparison->passed()) return FailureClass::RasterisationDiffers;
  return FailureClass::None;
}

std::string failure_class_name(FailureClass failure_class) {
  switch (failure_class) {
    case FailureClass::None: return "passed";
    case FailureClass::Nondeterminism: return "nondeterminism";
    case FailureClass::MissingGolden: return "missing golden";
    case FailureClass::SizeMismatch: return "size mismatch";
    case FailureClass::SimulationDiverged: return "simulation diverged";
    case FailureClass::NumericalNoise: return "numerical noise";
    case FailureClass::CannotTell: return "cannot tell";
    case FailureClass::BehaviourChanged: return "behaviour changed";
    case FailureClass::RasterisationDiffers: return "rasterisation differs";
    case FailureClass::NoRendererBaseline: return "no baseline for this renderer";
    case FailureClass::RendererBaselineRequired: return "renderer baseline required";
  }
  return "unknown";
}

std::string failure_class_id(FailureClass failure_class) {
  std::string id = failure_class_name(failure_class);
  for (char& c : id) {
    if (c == ' ') c = '_';
  }
  return id;
}

std::string failure_message(const GoldenCheck& check) {
  const FailureClass failure_class = classify_failure(check);
  std::ostringstream text;
  text << "golden '" << check.name << "': " << failure_class_name(failure_class) << ": ";
  switch (failure_class) {
    case FailureClass::None:
      text << check.comparison->message();
      break;
    case FailureClass::Nondeterminism:
      if (!check.second_render_identical) {
        text << "simulating and rendering the same frame twice in one process gave different "
                "results; tolerance never absorbs this. Look for uninitialised memory, "
                "unordered containers, thread-count-dependent reductions or time-dependent "
                "input";
      } else {
        text << "the same frame simulated and rendered in two separate processes gave "
                "different results (each process agrees with itself); tolerance never absorbs "
                "this and no golden is written from it. Look for values that depend on the "
                "process: addresses (pointer order or hashes under ASLR), the pid, the clock, "
                "the environment";
      }
      break;
    case FailureClass::MissingGolden:
      text << "no golden image exists. The actual image and its sidecar were written to "
              "the artifact directory; review them and promote with scripts/promote_goldens.sh";
      break;
    case FailureClass::SizeMismatch:
      text << "golden is " << check.comparison->expected_width << "x"
           << check.comparison->expected_height << ", actual is "
           << check.comparison->actual_width << "x" << check.comparison->actual_height;
      break;
    case FailureClass::SimulationDiverged:
      text << "physics state hash is " << image::to_hex_hash(check.actual_state_hash)
           << ", the golden's sidecar has " << image::to_hex_hash(*check.expected_state_hash)
           << " (and no noise envelope: re-promote to get one)" << kNextLine
           << "bodies that moved most: " << describe_drifts(check.moved_bodies) << kNextLine
           << image_text(check);
      break;
    case FailureClass::NumericalNoise:
      text << std::setprecision(3) << "every body and quantity stayed inside the golden's noise "
           << "envelope, and no body moved more than " << check.noise->largest_move
           << " m (bound " << check.noise->bound << " m, 1 % of the scene's size "
           << check.noise->scene_scale << " m)" << kNextLine
           << "a rounding change (reordered arithmetic, another compiler or flag): review the "
              "images and promote"
           << kNextLine << "bodies that moved most: " << describe_drifts(check.moved_bodies)
           << kNextLine << hashes(check) << kNextLine << image_text(check);
      break;
    case FailureClass::CannotTell:
      text << check.noise->describe_cannot_tell() << kNextLine
           << "do not promote on trust: check the change at an earlier frame, or a scene that "
              "is not chaotic"
           << kNextLine << "bodies that moved most: " << describe_drifts(check.moved_bodies)
           << kNextLine << hashes(check) << kNextLine << image_text(check);
      break;
    case FailureClass::BehaviourChanged:
      text << "the run left the golden's noise envelope (what rounding-sized perturbations do "
              "to this scene); largest escapes, relative to their envelope:"
           << kNextLine << check.noise->describe(kEscapesNamed, kNextLine) << kNextLine
           << "a physics change, not rounding: fix it, or promote only if it was meant"
           << kNextLine << hashes(check) << kNextLine << image_text(check);
      break;
    case FailureClass::NoRendererBaseline:
      text << "physics checked and matches (state hash " << image::to_hex_hash(check.actual_state_hash)
           << "); pixels not compared: the golden was drawn by '"
           << check.expected_renderer.describe() << "', this run by '"
           << check.actual_renderer.describe() << "', and there is no baseline for it. Add one "
           << "(written as " << check.renderer_baseline
           << ") with GOLDEN_UPDATE=missing ctest -R GoldenScenes (built-in goldens) or "
              "impulse2d golden update <scene file>";
      break;
    case FailureClass::RendererBaselineRequired:
      text << "pixels are required (--require-pixels or IMPULSE2D_REQUIRE_PIXELS=1) but this "
              "run's renderer '"
           << check.actual_renderer.describe() << "' has no baseline (the golden was drawn by '"
           << check.expected_renderer.describe() << "'); physics checked and matches (state hash "
           << image::to_hex_hash(check.actual_state_hash) << ")" << kNextLine
           << "add the baseline (written as " << check.renderer_baseline
           << ") on this renderer with GOLDEN_UPDATE=missing ctest -R GoldenScenes (built-in "
              "goldens) or impulse2d golden update <scene file>, review it and commit it";
      break;
    case FailureClass::RasterisationDiffers:
      text << "physics state matches (hash " << image::to_hex_hash(check.actual_state_hash)
           << ") but the image does not: " << check.comparison->message()
           << renderer_note(check);
      break;
  }
  return text.str();
}

}  // namespace impulse2d::golden

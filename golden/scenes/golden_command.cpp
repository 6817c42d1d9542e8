/// @file golden_command.cpp
#include "golden/scenes/golden_command.h"

#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <set>

#include "golden/error.h"
#include "golden/json_output.h"
#include "golden/junit.h"
#include "golden/pending_output.h"
#include "golden/report.h"
#include "golden/staged_update.h"
#include "golden/update_mode.h"
#include "golden/scenes/golden_plan.h"
#include "golden/scenes/noise_probe.h"
#include "golden/scenes/scene_frame.h"
#include "golden/scenes/second_process.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "image/png.h"
#include "render/frame_renderer.h"
#include "scene/interrupt.h"
#include "scene/usage_error.h"

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;

/// One renderer per frame size, created on first use.
class Renderers {
 public:
  render::FrameRenderer& of(int width, int height) {
    auto& renderer = renderers_[{width, height}];
    if (!renderer) renderer = std::make_unique<render::FrameRenderer>(width, height);
    return *renderer;
  }

 private:
  std::map<std::pair<int, int>, std::unique_ptr<render::FrameRenderer>> renderers_;
};

/// Writes the marker and this run's metadata (run.json) into the report being built.
void write_report_metadata(const fs::path& report, const GoldenCommandArguments& arguments) {
  image::write_text_file_atomically(report / kReportMarker, "");
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  nlohmann::json files = arguments.files;
  const nlohmann::json run = {{"command", "impulse2d golden " + arguments.action},
                              {"mode", arguments.action == "update"
                                           ? (arguments.all ? "update all" : "update changed")
                                           : "check, repeat " + std::to_string(arguments.repeat)},
                              {"date", date},
                              {"scene_files", files}};
  const fs::path file = report / "run.json";
  image::write_text_file_atomically(file, dump_json_for_file(run, file.string()));
}

int render_one_frame(const GoldenCommandArguments& arguments, const GoldenPlan& plan) {
  for (const GoldenSpec& spec : plan.scenes[0].frames) {
    if (spec.name != arguments.frame) continue;
    Renderers renderers;
    const ProducedFrame frame = produce_scene_frame(spec, renderers.of(spec.width, spec.height),
                                                    nullptr, arguments.start_run);
    image::save_png(arguments.out, frame.image);
    image::write_text_file_atomically(arguments.out + ".hash", image::to_hex_hash(frame.state_hash));
  }
  return kGoldenPassed;
}

/// Finishes or undoes, before anything reads them, the updates of `plan`'s golden folders
/// that a killed process left half-done, and says so on `err`.
void recover_interrupted_updates(const GoldenPlan& plan, std::ostream& err) {
  std::set<fs::path> done;
  for (const SceneGoldens& scene : plan.scenes) {
    if (!done.insert(scene.golden_dir).second) continue;
    const fs::path staging = scene.golden_dir / kStagingFolderName;
    switch (recover_interrupted_update(scene.golden_dir)) {
      case Recovery::RolledBack:
        err << "impulse2d: golden: removed " << staging.string()
            << ", left by an update that stopped before its commit (the goldens stayed as "
               "they were)\n";
        break;
      case Recovery::RolledForward:
        err << "impulse2d: golden: finished the commit of an update that stopped half-way ("
            << staging.string() << "): the goldens are its new set\n";
        break;
      case Recovery::None:
      case Recovery::Busy:
        break;
    }
  }
}

/// The check or update itself: every file it writes is prepared beside its place (the new
/// goldens in each golden folder's staging folder, the report as a hidden sibling, the JUnit
/// file under a hidden name) and moved into place only when all are ready.
int check_or_update(const GoldenCommandArguments& arguments, const GoldenPlan& plan,
                    std::ostream& out) {
  const bool update = arguments.action == "update";
  std::map<fs::path, std::unique_ptr<StagedUpdate>> staged;
  if (update) {
    for (const SceneGoldens& scene : plan.scenes) {
      auto& update_of_folder = staged[scene.golden_dir];
      if (!update_of_folder) update_of_folder = std::make_unique<StagedUpdate>(scene.golden_dir);
    }
  }
  PendingDirectory report(arguments.report_dir);
  write_report_metadata(report.path(), arguments);
  Renderers renderers;
  std::vector<JUnitCase> cases;
  int failed = 0;
  const bool require_pixels = !update && arguments.require_pixels;
  // Per renderer without a baseline: how many frames it drew (pixels unchecked or failed).
  std::map<std::string, std::size_t> without_baseline;
  for (const SceneGoldens& scene : plan.scenes) {
    CheckSettings settings;
    settings.golden_dir = scene.golden_dir;
    settings.artifact_root = report.path();
    settings.update_mode = !update ? UpdateMode::None
                           : arguments.all ? UpdateMode::All
                                           : UpdateMode::Changed;
    settings.repeat = arguments.repeat;
    settings.tolerance = scene.tolerance;
    settings.require_pixels = require_pixels;
    if (update) settings.write_dir = staged.at(scene.golden_dir)->path();
    const fs::path second_process_folder =
        update ? staged.at(scene.golden_dir)->scratch()
               : fs::temp_directory_path() / ("impulse2d-golden-" + std::to_string(::getpid()));
    for (const GoldenSpec& spec : scene.frames) {
      demos::check_interrupt();
      const auto start = std::chrono::steady_clock::now();
      CheckOutcome outcome = run_golden_check(
          spec.id(), spec.scene, static_cast<int>(spec.step),
          scene_frame_producer(spec, renderers.of(spec.width, spec.height)), settings,
          scene_noise_measurer(spec),
          other_process_producer(arguments.executable, spec, second_process_folder));
      // Named as they will be once the report is in place.
      if (!outcome.artifact_dir.empty()) outcome.artifact_dir = report.final_path(outcome.artifact_dir);
      if (!outcome.report.empty()) outcome.report = report.final_path(outcome.report);
      JUnitCase test;
      test.classname = spec.scene;
      test.name = spec.name;
      test.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      test.failed = !outcome.passed();
      if (outcome.check.renderer_baseline_missing && !outcome.golden_written) {
        ++without_baseline[outcome.check.actual_renderer.describe()];
      }
      if (test.failed) {
        ++failed;
        test.failure_type = failure_class_id(outcome.failure_class);
        test.failure_message = outcome.message();
        out << "FAIL " << outcome.message() << "\n";
      } else if (outcome.failure_class == FailureClass::NoRendererBaseline &&
                 !outcome.golden_written) {
        test.skipped = "no baseline for this renderer (physics checked and matches)";
        out << "skip " << outcome.message() << "\n";
      } else {
        out << (outcome.golden_written ? "WROTE " : "ok   ") << spec.id() << "\n";
      }
      cases.push_back(std::move(test));
    }
  }
  write_html_report(report.path());
  std::optional<PendingFile> junit;
  if (!arguments.junit.empty()) junit.emplace(arguments.junit, junit_xml("impulse2d golden", cases));
  demos::check_interrupt();

  // The commit: renames only. A signal from here on is acted on once it is done.
  for (auto& [folder, update_of_folder] : staged) update_of_folder->commit();
  if (junit) junit->commit();
  report.commit();

  std::size_t physics_only = 0;
  for (const JUnitCase& test : cases) physics_only += test.skipped.empty() ? 0 : 1;
  out << cases.size() - failed << " of " << cases.size() << " goldens "
      << (update ? "match or were written" : "match");
  if (physics_only > 0) {
    out << " (" << physics_only << " by their physics only: no baseline for this renderer)";
  }
  out << "; report: " << (fs::path(arguments.report_dir) / "index.html").string() << "\n";
  // Once per run: which renderer lacks baselines, so a CI image whose GL_RENDERER or
  // GL_VERSION changed does not stop checking pixels unnoticed.
  for (const auto& [renderer, count] : without_baseline) {
    out << "pixels " << (require_pixels ? "required but not checked" : "unchecked") << ": "
        << count << " of " << cases.size() << " frames drawn by '" << renderer
        << "', which has no baseline; "
        << (require_pixels ? "they failed (--require-pixels)"
                           : "their physics was checked (fail instead: --require-pixels or "
                             "IMPULSE2D_REQUIRE_PIXELS=1)")
        << "; add baselines on this renderer with impulse2d golden update <scene files>\n";
  }
  return failed == 0 ? kGoldenPassed : kGoldenFailed;
}

/// What an interrupted or failed run left, for its message.
std::string nothing_changed(const GoldenCommandArguments& arguments) {
  std::vector<std::string> kept;
  if (arguments.action == "update") kept.push_back("the goldens");
  kept.push_back("the report");
  if (!arguments.junit.empty()) kept.push_back("the JUnit file");
  std::string text = "; nothing was changed: ";
  for (std::size_t i = 0; i < kept.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == kept.size() ? " and " : ", ") + kept[i];
  }
  return text + (kept.size() == 1 ? " is" : " are") +
         " as they were (what was staged for them was removed)";
}

}  // namespace

void dry_run_golden_command(const GoldenCommandArguments& arguments, std::ostream& out) {
  const GoldenPlan plan = plan_golden_command(arguments);
  if (arguments.action == "frame" && arguments.start_run) {
    // The saved state is checked as the run checks it (nothing is stepped or rendered).
    for (const GoldenSpec& spec : plan.scenes[0].frames) {
      if (spec.name != arguments.frame) continue;
      GoldenRun golden_run(spec);
      start_golden_run(spec, golden_run, arguments.start_run);
    }
  }
  print_golden_plan(arguments, plan, out);
}

int run_golden_command(const GoldenCommandArguments& arguments, std::ostream& out,
                       std::ostream& err) {
  try {
    const GoldenPlan plan = plan_golden_command(arguments);
    if (arguments.action == "frame") return render_one_frame(arguments, plan);
    recover_interrupted_updates(plan, err);
    GoldenCommandArguments effective = arguments;
    try {
      effective.require_pixels = arguments.require_pixels || require_pixels_from_environment();
    } catch (const GoldenError& error) {
      throw demos::UsageError(error.what());
    }
    int status = kGoldenFailed;
    try {
      status = check_or_update(effective, plan, out);
    } catch (const demos::Interrupted& interrupted) {
      throw demos::Interrupted(interrupted.signal_number(),
                               interrupted.what() + nothing_changed(arguments));
    } catch (const GoldenError& error) {
      throw GoldenError(error.what() + nothing_changed(arguments));
    }
    // A signal during the commit (renames only) is acted on once it is done.
    const int signal_number = demos::pending_signal();
    if (signal_number != 0) {
      throw demos::Interrupted(signal_number, "interrupted by " + demos::signal_name(signal_number) +
                                                  " after the run had finished and its files "
                                                  "were in place");
    }
    return status;
  } catch (const demos::Interrupted&) {
    throw;
  } catch (const demos::UsageError& error) {
    err << "impulse2d: golden: " << error.what() << "\n";
    return kGoldenBadInput;
  } catch (const std::exception& error) {
    err << "impulse2d: golden: error: " << error.what() << "\n";
    return kGoldenFailed;
  }
}

}  // namespace impulse2d::golden

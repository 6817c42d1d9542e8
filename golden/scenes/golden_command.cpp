/// @file golden_command.cpp
#include "image/png.h"
#include "golden/scenes/golden_command.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "scene/usage_error.h"
#include "render/frame_renderer.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "golden/junit.h"
#include "golden/report.h"
#include "golden/update_mode.h"
#include "golden/scenes/golden_block.h"
#include "golden/scenes/noise_probe.h"
#include "golden/scenes/scene_frame.h"

extern char** environ;

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;

/// The file that marks a directory as this command's report, so a run may empty it.
constexpr const char* kReportMarker = ".impulse2d-golden-report";

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

/// Runs `arguments` as a child process and waits; returns its exit status (-1: not run).
int run_child(const std::vector<std::string>& arguments) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  if (::posix_spawn(&child, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (::waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// `impulse2d golden frame` of `spec` in a child process.
FrameProducer other_process_producer(const std::string& executable, const GoldenSpec& spec) {
  return [executable, spec] {
    const fs::path directory =
        fs::temp_directory_path() / ("impulse2d-golden-" + std::to_string(::getpid()));
    fs::create_directories(directory);
    const fs::path png = directory / "frame.png";
    const int status = run_child(
        {executable, "golden", "frame", spec.scene_file, spec.name, "--out", png.string()});
    ProducedFrame frame;
    std::optional<std::uint64_t> hash;
    if (status == 0 && fs::exists(png)) {
      frame.image = image::load_png(png);
      hash = image::parse_hex_hash(image::read_text_file(png.string() + ".hash"));
    }
    std::error_code ignored;
    fs::remove_all(directory, ignored);
    if (!hash) {
      throw GoldenError("golden '" + spec.id() + "': the second process (" + executable +
                        " golden frame) failed with status " + std::to_string(status));
    }
    frame.state_hash = *hash;
    return frame;
  };
}

/// Empties the report directory of an earlier run (only one this command made) and writes
/// this run's metadata into it.
void prepare_report(const fs::path& root, const GoldenCommandArguments& arguments) {
  if (fs::exists(root)) {
    if (!fs::is_directory(root) ||
        (!fs::is_empty(root) && !fs::exists(root / kReportMarker))) {
      throw demos::UsageError("--report " + root.string() +
                              ": exists and is not a golden report of an earlier run; choose "
                              "another directory or remove it");
    }
    fs::remove_all(root);
  }
  fs::create_directories(root);
  image::write_text_file_atomically(root / kReportMarker, "");
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
  image::write_text_file_atomically(root / "run.json", run.dump(2) + "\n");
}

/// `read_scene_goldens`, its errors as usage errors (bad input, exit status 2).
SceneGoldens read_goldens(const std::string& file) {
  try {
    return read_scene_goldens(file);
  } catch (const GoldenError& error) {
    throw demos::UsageError(error.what());
  }
}

int render_one_frame(const GoldenCommandArguments& arguments) {
  if (arguments.files.size() != 1 || arguments.out.empty()) {
    throw demos::UsageError("golden frame: give one scene file, a frame name and --out PNG");
  }
  const SceneGoldens goldens = read_goldens(arguments.files[0]);
  for (const GoldenSpec& spec : goldens.frames) {
    if (spec.name != arguments.frame) continue;
    Renderers renderers;
    const ProducedFrame frame = produce_scene_frame(spec, renderers.of(spec.width, spec.height));
    image::save_png(arguments.out, frame.image);
    image::write_text_file_atomically(arguments.out + ".hash", image::to_hex_hash(frame.state_hash));
    return kGoldenPassed;
  }
  throw demos::UsageError(arguments.files[0] + ": no golden frame named '" + arguments.frame +
                          "'");
}

int check_or_update(const GoldenCommandArguments& arguments, std::ostream& out) {
  if (arguments.files.empty()) throw demos::UsageError("golden: give at least one scene file");
  if (arguments.repeat != 1 && arguments.repeat != 2) {
    throw demos::UsageError("--repeat " + std::to_string(arguments.repeat) + ": must be 1 or 2");
  }
  const bool update = arguments.action == "update";
  if (update && is_ci(std::getenv("CI"))) {
    throw demos::UsageError("golden update refused: CI is set, and CI never writes its own "
                            "goldens; run it locally and commit the reviewed goldens");
  }
  std::vector<SceneGoldens> scenes;
  for (const std::string& file : arguments.files) scenes.push_back(read_goldens(file));

  const fs::path root = arguments.report_dir;
  prepare_report(root, arguments);
  Renderers renderers;
  std::vector<JUnitCase> cases;
  int failed = 0;
  for (const SceneGoldens& scene : scenes) {
    CheckSettings settings;
    settings.golden_dir = scene.golden_dir;
    settings.artifact_root = root;
    settings.update_mode = !update ? UpdateMode::None
                           : arguments.all ? UpdateMode::All
                                           : UpdateMode::Changed;
    settings.repeat = arguments.repeat;
    settings.tolerance = scene.tolerance;
    for (const GoldenSpec& spec : scene.frames) {
      const auto start = std::chrono::steady_clock::now();
      const CheckOutcome outcome = run_golden_check(
          spec.id(), spec.scene, static_cast<int>(spec.step),
          scene_frame_producer(spec, renderers.of(spec.width, spec.height)), settings,
          scene_noise_measurer(spec), other_process_producer(arguments.executable, spec));
      JUnitCase test;
      test.classname = spec.scene;
      test.name = spec.name;
      test.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      test.failed = !outcome.passed();
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
  write_html_report(root);
  if (!arguments.junit.empty()) write_junit(arguments.junit, "impulse2d golden", cases);
  std::size_t physics_only = 0;
  for (const JUnitCase& test : cases) physics_only += test.skipped.empty() ? 0 : 1;
  out << cases.size() - failed << " of " << cases.size() << " goldens "
      << (update ? "match or were written" : "match");
  if (physics_only > 0) {
    out << " (" << physics_only << " by their physics only: no baseline for this renderer)";
  }
  out << "; report: " << (root / "index.html").string() << "\n";
  return failed == 0 ? kGoldenPassed : kGoldenFailed;
}

}  // namespace

int run_golden_command(const GoldenCommandArguments& arguments, std::ostream& out,
                       std::ostream& err) {
  try {
    if (arguments.action == "frame") return render_one_frame(arguments);
    return check_or_update(arguments, out);
  } catch (const demos::UsageError& error) {
    err << "impulse2d: golden: " << error.what() << "\n";
    return kGoldenBadInput;
  } catch (const std::exception& error) {
    err << "impulse2d: golden: error: " << error.what() << "\n";
    return kGoldenFailed;
  }
}

}  // namespace impulse2d::golden

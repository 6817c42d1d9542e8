/// @file golden_plan.cpp
#include "golden/scenes/golden_plan.h"

#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <set>

#include "golden/check_run.h"
#include "golden/error.h"
#include "golden/output_path.h"
#include "golden/sidecar.h"
#include "golden/staged_update.h"
#include "golden/update_mode.h"
#include "scene/usage_error.h"

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;

/// `check_output_path`, its error as bad input.
void require_writable(const fs::path& path, const std::string& option, bool folder) {
  try {
    check_output_path(path, option, folder);
  } catch (const GoldenError& error) {
    throw demos::UsageError(error.what());
  }
}

/// `read_scene_goldens`, its errors as usage errors (bad input, exit status 2).
SceneGoldens read_goldens(const std::string& file) {
  try {
    return read_scene_goldens(file);
  } catch (const GoldenError& error) {
    throw demos::UsageError(error.what());
  }
}

/// "a, b and c" of at most `shown` items, then "and N more".
std::string list(const std::vector<std::string>& items, std::size_t shown = 8) {
  std::string text;
  for (std::size_t i = 0; i < items.size() && i < shown; ++i) {
    text += (i == 0 ? "" : ", ") + items[i];
  }
  if (items.size() > shown) text += " and " + std::to_string(items.size() - shown) + " more";
  return text;
}

}  // namespace

namespace {

GoldenPlan plan_golden_files(const GoldenCommandArguments& arguments) {
  GoldenPlan plan;
  if (arguments.action == "frame") {
    if (arguments.files.size() != 1 || arguments.out.empty()) {
      throw demos::UsageError("golden frame: give one scene file, a frame name and --out PNG");
    }
    plan.scenes.push_back(read_goldens(arguments.files[0]));
    bool found = false;
    for (const GoldenSpec& spec : plan.scenes[0].frames) found = found || spec.name == arguments.frame;
    if (!found) {
      throw demos::UsageError(arguments.files[0] + ": no golden frame named '" +
                              arguments.frame + "'");
    }
    require_writable(arguments.out, "--out", false);
    require_writable(arguments.out + ".hash", "--out", false);
    return plan;
  }
  if (arguments.files.empty()) throw demos::UsageError("golden: give at least one scene file");
  if (arguments.repeat != 1 && arguments.repeat != 2) {
    throw demos::UsageError("--repeat " + std::to_string(arguments.repeat) + ": must be 1 or 2");
  }
  try {
    require_pixels_from_environment();
  } catch (const GoldenError& error) {
    throw demos::UsageError(error.what());
  }
  if (arguments.action == "update" && is_ci(std::getenv("CI"))) {
    throw demos::UsageError("golden update refused: CI is set, and CI never writes its own "
                            "goldens; run it locally and commit the reviewed goldens");
  }
  for (const std::string& file : arguments.files) plan.scenes.push_back(read_goldens(file));

  const fs::path report = arguments.report_dir;
  require_writable(report, "--report", true);
  std::error_code error;
  if (fs::is_directory(report, error) && !fs::is_empty(report, error) &&
      !fs::exists(report / kReportMarker)) {
    throw demos::UsageError("--report " + report.string() +
                            ": exists and is not a golden report of an earlier run; choose "
                            "another directory or remove it");
  }
  if (!arguments.junit.empty()) require_writable(arguments.junit, "--junit", false);
  return plan;
}

}  // namespace

GoldenPlan plan_golden_command(const GoldenCommandArguments& arguments) {
  if (arguments.workers < 1 || arguments.workers > 64) {
    throw demos::UsageError("--workers " + std::to_string(arguments.workers) + ": must be 1..64");
  }
  GoldenPlan plan = plan_golden_files(arguments);
  for (SceneGoldens& scene : plan.scenes) {
    for (GoldenSpec& spec : scene.frames) spec.worker_count = arguments.workers;
  }
  return plan;
}

void print_golden_plan(const GoldenCommandArguments& arguments, const GoldenPlan& plan,
                       std::ostream& out) {
  out << "golden " << arguments.action << ": dry run; nothing is rendered or written\n";
  if (arguments.action == "frame") {
    for (const GoldenSpec& spec : plan.scenes[0].frames) {
      if (spec.name != arguments.frame) continue;
      out << "would render " << spec.id() << " (" << spec.scene_file << ", step " << spec.step
          << ", " << spec.width << "x" << spec.height << ")\nwould write: " << arguments.out
          << ", " << arguments.out << ".hash\n";
    }
    return;
  }
  const bool update = arguments.action == "update";
  out << "scene files (" << arguments.files.size() << "): " << list(arguments.files) << "\n";
  std::size_t count = 0;
  for (const SceneGoldens& scene : plan.scenes) count += scene.frames.size();
  out << "goldens (" << count << "):\n";
  std::set<fs::path> golden_dirs;
  std::vector<std::string> missing;
  for (const SceneGoldens& scene : plan.scenes) {
    golden_dirs.insert(scene.golden_dir);
    for (const GoldenSpec& spec : scene.frames) {
      const fs::path png = golden_png_path(scene.golden_dir, spec.id());
      const bool present = fs::exists(png) && fs::exists(sidecar_path_for(png));
      if (!present) missing.push_back(spec.id());
      out << "  " << png.string() << " + .json" << (present ? "" : " (missing)") << "\n";
    }
  }
  for (const fs::path& dir : golden_dirs) {
    const std::string interrupted = describe_interrupted_update(dir);
    if (!interrupted.empty()) out << "first: " << interrupted << "\n";
  }
  out << "would write:\n";
  if (update) {
    out << "  goldens: " << (arguments.all ? "all " + std::to_string(count)
                                           : "the missing (" + std::to_string(missing.size()) +
                                                 ") and the failing ones, up to " +
                                                 std::to_string(count))
        << ", each after a second process rendered it, staged in";
    for (const fs::path& dir : golden_dirs) out << " " << (dir / kStagingFolderName).string();
    out << " and moved into place together once all are written\n";
  } else {
    out << "  goldens: none (check)";
    if (arguments.repeat == 2) out << "; a second process renders each frame";
    if (arguments.require_pixels || require_pixels_from_environment()) {
      out << "; a frame whose renderer has no baseline fails (pixels required)";
    }
    out << "\n";
  }
  out << "  report: " << arguments.report_dir << "/ (replaced; index.html and the failures' "
      << "artifacts)\n";
  if (!arguments.junit.empty()) out << "  junit: " << arguments.junit << "\n";
}

}  // namespace impulse2d::golden

/// @file tune_command.cpp
/// `impulse2d tune` (lab and lab merge: lab_command.cpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "demos/scene_registry.h"
#include "frames/progress.h"
#include "image/file_io.h"
#include "lab/engine_simulation.h"
#include "lab/json_number.h"
#include "lab/lab_command.h"
#include "lab/lab_output.h"
#include "lab/lab_tune.h"
#include "lab/option_numbers.h"
#include "lab/work_budget.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

/// Steps of the scene's own method timed to estimate tune's minutes.
constexpr int probe_steps = 20;

/// Everything `tune` checked and decided before any work.
struct TunePlan {
  demos::Scene scene;          ///< the resolved scene
  demos::Params params;        ///< its parameters with --param applied
  TuneOptions options;         ///< bound, metric, duration, repeats
  std::size_t candidates = 0;  ///< candidates searched
  WorkEstimate work;           ///< runs and steps at most
};

/// Parses and checks everything `tune` needs; throws `demos::UsageError` before any work.
TunePlan make_tune_plan(const TuneArguments& arguments) {
  TunePlan plan{demos::resolve_scene(arguments.scene), demos::Params(), TuneOptions(), 0, WorkEstimate()};
  plan.params = demos::Params(plan.scene.params);
  for (const std::string& assignment : arguments.params) plan.params.set_assignment(assignment);
  TuneOptions& options = plan.options;
  options.max_error = decimal_option("--max-error", arguments.max_error, 0.0, 1000.0, "m");
  options.repeats = static_cast<int>(count_option("--repeats", arguments.repeats, 1, 100));
  if (arguments.metric == "final") {
    options.metric = TuneMetric::Final;
  } else if (arguments.metric == "trajectory") {
    options.metric = TuneMetric::Trajectory;
  } else {
    throw demos::UsageError("--metric '" + arguments.metric + "': expected final or trajectory");
  }
  options.duration = arguments.duration.empty()
                         ? static_cast<double>(plan.scene.view.steps) * plan.scene.settings.time_step
                         : decimal_option("--duration", arguments.duration, 0.0, 3600.0, "s");
  if (!(options.duration > 0.0 && options.duration <= 3600.0)) {
    throw demos::UsageError("the scene's run lasts " + std::to_string(options.duration) +
                            " s; give --duration in (0, 3600] s");
  }
  options.quick = arguments.quick;
  if (!arguments.out.empty()) {
    if (std::filesystem::path(arguments.out).extension() != ".json") {
      throw demos::UsageError("--out " + arguments.out + ": must end in .json");
    }
    check_output_file(arguments.out, "--out");
  }
  // The work at most: every run of every method searched, each timed `repeats` times.
  std::vector<LabMethod> methods = tune_candidates(plan.scene, options.quick);
  plan.candidates = methods.size();
  methods.push_back(tune_reference(plan.scene));
  methods.push_back(scene_method(plan.scene));
  EngineSimulation probe(plan.scene, scene_method(plan.scene), plan.params);
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < probe_steps; ++step) probe.step();
  const double probe_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / probe_steps;
  for (const LabMethod& method : methods) {
    const std::int64_t steps = std::llround(options.duration / method.time_step);
    plan.work.steps += steps * (1 + options.repeats);
    plan.work.seconds += probe_seconds * static_cast<double>(steps * (1 + options.repeats));
  }
  plan.work.runs = tune_runs(plan.candidates, options.repeats);
  check_budget("tune", plan.work, plan.work.steps, max_tune_steps, "steps", arguments.force,
               "a shorter --duration, fewer --repeats or --quick");
  return plan;
}

/// The figures of a tune run as a JSON object (without the settings).
nlohmann::ordered_json figures(const TunePlan& plan, const TuneArguments& arguments,
                               const TuneResult& result) {
  nlohmann::ordered_json record;
  record["scene"] = plan.scene.name;
  record["max_error"] = json_number(plan.options.max_error, "max_error");
  record["metric"] = arguments.metric;
  record["duration"] = json_number(plan.options.duration, "duration");
  record["found"] = result.found;
  if (result.found) {
    record["method"] = method_label(result.chosen.method);
    record["error"] = json_number(result.chosen.error, "error");
    record["us_per_simulated_second"] =
        json_number(result.chosen.us_per_simulated_second, "us_per_simulated_second");
  }
  record["scene_own_method"] = method_label(result.scene_default.method);
  // A scene whose own method diverges has no finite error: null.
  record["scene_own_error"] = std::isfinite(result.scene_default.error)
                                  ? nlohmann::ordered_json(result.scene_default.error)
                                  : nlohmann::ordered_json(nullptr);
  if (result.found) {
    record["scene_own_us_per_simulated_second"] = json_number(
        result.scene_default.us_per_simulated_second, "scene_own_us_per_simulated_second");
    record["reference_method"] = method_label(result.reference.method);
    record["reference_us_per_simulated_second"] = json_number(
        result.reference.us_per_simulated_second, "reference_us_per_simulated_second");
  } else {
    record["candidates"] = result.candidates.size();
  }
  return record;
}

}  // namespace

void plan_tune(const TuneArguments& arguments, std::ostream& out) {
  const TunePlan plan = make_tune_plan(arguments);
  out << "tune " << plan.scene.name << ": " << plan.candidates << " candidates, "
      << plan.options.repeats << " repeats over " << plan.options.duration << " s: at most "
      << describe_work(plan.work) << "; the bound is " << grouped(max_tune_steps) << " steps"
      << (plan.work.steps > max_tune_steps ? " (--force)" : "") << "\n";
  if (!arguments.out.empty()) out << "would write " << arguments.out << "\n";
}

void run_tune(const TuneArguments& arguments, std::ostream& out) {
  TunePlan plan = make_tune_plan(arguments);
  std::unique_ptr<demos::Progress> bar;
  std::int64_t known_total = 0;
  plan.options.progress = [&](std::int64_t done, std::int64_t total) {
    if (arguments.quiet) return;
    if (!bar || total != known_total) {
      bar = std::make_unique<demos::Progress>("tune", total, stderr, demos::is_terminal(stderr), "runs");
      known_total = total;
    }
    bar->update(done);
  };
  const TuneResult result = tune_scene(plan.scene, plan.params, plan.options);
  if (bar) bar->finish();
  const TuneOptions& options = plan.options;

  char line[512];
  std::snprintf(line, sizeof line,
                "tune %s: %zu candidates, metric %s over %.3g s, bound %.4g m; reference %s "
                "(%.0f us/s)\n",
                plan.scene.name.c_str(), result.candidates.size(), arguments.metric.c_str(),
                options.duration, options.max_error, method_label(result.reference.method).c_str(),
                result.reference.us_per_simulated_second);
  out << line;
  std::snprintf(line, sizeof line, "scene's own method %s: error %.4g m, %.0f us/s\n",
                method_label(result.scene_default.method).c_str(), result.scene_default.error,
                result.scene_default.us_per_simulated_second);
  out << line;
  nlohmann::ordered_json record = figures(plan, arguments, result);
  if (!result.found) {
    out << "no candidate stays within " << options.max_error
        << " m of the reference: keep the scene's method or loosen --max-error\n";
  } else {
    const double versus_own =
        result.scene_default.us_per_simulated_second / result.chosen.us_per_simulated_second;
    const double versus_reference =
        result.reference.us_per_simulated_second / result.chosen.us_per_simulated_second;
    std::snprintf(line, sizeof line,
                  "cheapest within the bound: %s: error %.4g m, %.0f us/s: %.2fx %s than the "
                  "scene's own method (which is %s the bound), %.2fx cheaper than the reference\n",
                  method_label(result.chosen.method).c_str(), result.chosen.error,
                  result.chosen.us_per_simulated_second,
                  versus_own >= 1.0 ? versus_own : 1.0 / versus_own,
                  versus_own >= 1.0 ? "cheaper" : "dearer",
                  result.scene_default.error <= options.max_error ? "within" : "outside",
                  versus_reference);
    const nlohmann::ordered_json settings = tuned_settings(result.chosen.method, plan.scene.model);
    out << line << settings.dump(2) << "\n";
    record.update(settings);
  }
  if (!arguments.out.empty()) {
    image::write_text_file_atomically(arguments.out, record.dump(2) + "\n");
    out << "wrote " << arguments.out << "\n";
  }
}

}  // namespace impulse2d::lab

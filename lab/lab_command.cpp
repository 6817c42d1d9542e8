/// @file lab_command.cpp
#include "lab/lab_command.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lab/gnuplot.h"
#include "lab/lab_chart.h"
#include "lab/lab_peers.h"
#include "lab/lab_sweep.h"
#include "lab/lab_tune.h"
#include "lab/stability_map.h"
#include <filesystem>
#include "demos/scene_registry.h"
#include "frames/progress.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw demos::UsageError(path + ": cannot read");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string results_csv(const std::vector<LabResult>& results) {
  std::string text = csv_header() + "\n";
  for (const LabResult& result : results) text += csv_line(result) + "\n";
  return text;
}

/// Prints per scenario: how many methods pass, the recommended one and the peers' errors.
void summarise(const std::vector<LabResult>& results, std::ostream& out) {
  std::string scenario;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].scenario == scenario) continue;
    scenario = results[i].scenario;
    int passing = 0, total = 0;
    const LabResult* recommended = nullptr;
    std::string peers;
    for (std::size_t j = i; j < results.size() && results[j].scenario == scenario; ++j) {
      const LabResult& row = results[j];
      if (row.method.engine != Engine::Impulse2d) {
        char text[160];
        std::snprintf(text, sizeof text, "; %s %.3g %s (%s)", method_label(row.method).c_str(),
                      row.error, row.unit.c_str(), row.pass ? "pass" : "fail");
        peers += text;
        continue;
      }
      ++total;
      passing += row.pass ? 1 : 0;
      if (row.recommended) recommended = &row;
    }
    char line[400];
    if (recommended) {
      std::snprintf(line, sizeof line, "%-20s %2d/%2d methods pass; cheapest: %s, error %.3g %s, %.1f us/s",
                    scenario.c_str(), passing, total, method_label(recommended->method).c_str(),
                    recommended->error, recommended->unit.c_str(),
                    recommended->us_per_simulated_second);
    } else {
      std::snprintf(line, sizeof line, "%-20s %2d/%2d methods pass", scenario.c_str(), passing, total);
    }
    out << line << peers << "\n";
  }
}

void draw_charts_if_possible(const std::vector<LabResult>& results, const std::string& directory,
                             std::ostream& out) {
  if (!gnuplot_available()) {
    std::fprintf(stderr,
                 "impulse2d lab: gnuplot not found: charts skipped (apt-get install gnuplot-nox)\n");
    return;
  }
  const std::vector<std::string> charts = draw_lab_charts(results, directory);
  out << "wrote " << charts.size() << " charts to " << directory << "/\n";
}

/// Runs the stability map; writes stability.csv, stability.png and boundary contact sheets.
void run_stability(bool quick, bool charts, bool quiet, const std::string& directory,
                   std::ostream& out) {
  const std::vector<Stressor> list = stressors(quick);
  const std::vector<LabMethod> methods = stability_methods(quick);
  std::unique_ptr<demos::Progress> bar;
  const auto progress = [&](int done, int total) {
    if (quiet) return;
    if (!bar) bar = std::make_unique<demos::Progress>("stability map", total, stderr,
                                                      demos::is_terminal(stderr), "cells");
    bar->update(done);
  };
  const std::vector<StabilityCell> cells = run_stability_map(list, methods, quick ? 0 : 4, progress);
  if (bar) bar->finish();
  write_file_atomically(directory + "/stability.csv", stability_csv(cells));
  out << "wrote the stability map (" << methods.size() << " methods x " << list.size()
      << " stressors) to " << directory << "/stability.csv\n";
  for (const StabilityCell& cell : cells) {
    char line[400];
    if (!cell.any_pass) {
      std::snprintf(line, sizeof line, "  %-22s %-16s fails the easiest (%s)\n",
                    method_label(cell.method).c_str(), cell.stressor.c_str(), cell.fail_reason.c_str());
    } else if (cell.all_pass) {
      std::snprintf(line, sizeof line, "  %-22s %-16s passes every value, to %.4g %s\n",
                    method_label(cell.method).c_str(), cell.stressor.c_str(), cell.last_pass,
                    cell.unit.c_str());
    } else {
      std::snprintf(line, sizeof line, "  %-22s %-16s passes %.4g, fails %.4g %s (%s)\n",
                    method_label(cell.method).c_str(), cell.stressor.c_str(), cell.last_pass,
                    cell.first_fail, cell.unit.c_str(), cell.fail_reason.c_str());
    }
    out << line;
  }
  if (!charts) return;
  if (gnuplot_available()) {
    draw_stability_heat_map(cells, list, directory + "/stability.png");
    out << "wrote " << directory << "/stability.png\n";
  }
  // Contact sheets of a few boundaries: the final frame on each side.
  // (Only cells with a boundary are drawn: a method that passes a whole ladder has none.)
  const std::string standard = method_label(LabMethod{});
  const std::string accumulated = method_label(method_for(SolverMethod::Accumulated));
  const std::vector<std::pair<std::string, std::string>> boundaries = {
      {standard, "stack_height"},   {standard, "time_step"},
      {standard, "friction_angle"}, {standard, "elastic_pile"},
      {standard + " noccd nospec", "bullet_speed"}, {accumulated, "elastic_pile"}};
  std::filesystem::create_directories(directory + "/stability_sheets");
  for (const auto& [label, stressor_name] : boundaries) {
    for (const StabilityCell& cell : cells) {
      if (method_label(cell.method) != label || cell.stressor != stressor_name) continue;
      if (!cell.any_pass || cell.all_pass || cell.method.engine != Engine::Impulse2d) continue;
      for (const Stressor& stressor : list) {
        if (stressor.name != stressor_name) continue;
        std::string file = label + "_" + stressor_name;
        for (char& c : file) c = (c == ' ' || c == '/') ? '_' : c;
        const std::string path = directory + "/stability_sheets/" + file + ".png";
        draw_boundary_sheet(stressor, cell, path);
        out << "wrote " << path << "\n";
      }
    }
  }
}

}  // namespace

std::pair<int, int> parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  int index = 0, count = 0;
  char tail = 0;
  if (slash == std::string::npos ||
      std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &tail) != 2 || count < 1 ||
      index < 1 || index > count) {
    throw demos::UsageError("--shard '" + text + "': expected K/N with 1 <= K <= N, e.g. 2/4");
  }
  return {index, count};
}

void run_lab(const LabArguments& arguments, std::ostream& out) {
  const auto [shard_index, shard_count] = parse_shard(arguments.shard);
  if (arguments.repeats < 0 || arguments.repeats > 100)
    throw demos::UsageError("--repeats must be 1..100");
  const std::string directory =
      arguments.scenarios.empty() ? default_scenario_directory() : arguments.scenarios;
  std::vector<LabScenario> scenarios = load_lab_scenarios(directory);
  if (!arguments.only.empty()) {
    std::vector<LabScenario> chosen;
    for (const std::string& name : arguments.only) {
      bool found = false;
      for (const LabScenario& scenario : scenarios) {
        if (scenario.name == name) {
          chosen.push_back(scenario);
          found = true;
        }
      }
      if (!found) throw demos::UsageError("--only " + name + ": no such scenario in " + directory);
    }
    scenarios = chosen;
  }
  for (const Engine peer : {Engine::Box2d, Engine::Chipmunk}) {
    const std::string note = engine_note(peer);
    if (arguments.peers && !note.empty()) std::fprintf(stderr, "impulse2d lab: %s\n", note.c_str());
  }

  if (!arguments.sweep) {
    if (!arguments.stability) throw demos::UsageError("--no-sweep with --no-stability leaves nothing to run");
    run_stability(arguments.quick, arguments.charts, arguments.quiet, arguments.out, out);
    return;
  }
  SweepOptions options;
  options.quick = arguments.quick;
  options.repeats = arguments.repeats > 0 ? arguments.repeats : (arguments.quick ? 2 : 3);
  options.shard_index = shard_index - 1;
  options.shard_count = shard_count;
  options.peers = arguments.peers;
  std::int64_t known_total = 0;
  std::unique_ptr<demos::Progress> bar;
  options.progress = [&](std::int64_t done, std::int64_t total) {
    if (arguments.quiet) return;
    if (!bar || total != known_total) {
      bar = std::make_unique<demos::Progress>("lab sweep", total, stderr, demos::is_terminal(stderr),
                                             "runs");
      known_total = total;
    }
    bar->update(done);
  };
  const auto start = std::chrono::steady_clock::now();
  const std::vector<LabResult> results = run_sweep(scenarios, options);
  if (bar) bar->finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string csv_path =
      arguments.out + (shard_count == 1 ? std::string("/lab.csv")
                                        : "/lab_shard_" + std::to_string(shard_index) + "_of_" +
                                              std::to_string(shard_count) + ".csv");
  write_file_atomically(csv_path, results_csv(results));
  out << "wrote " << results.size() << " rows (" << scenarios.size() << " scenarios, "
      << options.repeats << " interleaved repeats, " << static_cast<int>(seconds) << " s) to "
      << csv_path << "\n";
  summarise(results, out);
  if (arguments.charts && shard_count == 1) draw_charts_if_possible(results, arguments.out + "/charts", out);
  if (arguments.stability && shard_count == 1) run_stability(arguments.quick, arguments.charts, arguments.quiet, arguments.out, out);
}

void merge_lab(const MergeArguments& arguments, std::ostream& out) {
  if (arguments.inputs.empty()) throw demos::UsageError("lab merge: give the shard CSV files to join");
  std::vector<LabResult> results;
  for (const std::string& input : arguments.inputs) {
    for (LabResult& row : parse_csv(read_text(input), input)) results.push_back(row);
  }
  std::stable_sort(results.begin(), results.end(),
                   [](const LabResult& a, const LabResult& b) { return a.job < b.job; });
  for (std::size_t i = 1; i < results.size(); ++i) {
    if (results[i].job == results[i - 1].job) {
      throw demos::UsageError("lab merge: job " + std::to_string(results[i].job) +
                              " appears twice (the same shard given twice?)");
    }
  }
  mark_fronts(results);
  const std::string csv_path = arguments.out + "/lab.csv";
  write_file_atomically(csv_path, results_csv(results));
  out << "merged " << arguments.inputs.size() << " files, " << results.size() << " rows into "
      << csv_path << "\n";
  summarise(results, out);
  if (arguments.charts) draw_charts_if_possible(results, arguments.out + "/charts", out);
}

void run_tune(const TuneArguments& arguments, std::ostream& out) {
  const demos::Scene scene = demos::resolve_scene(arguments.scene);
  demos::Params params(scene.params);
  for (const std::string& assignment : arguments.params) params.set_assignment(assignment);
  if (!(arguments.max_error > 0.0)) throw demos::UsageError("--max-error must be > 0 (metres)");
  if (arguments.repeats < 1 || arguments.repeats > 100) throw demos::UsageError("--repeats must be 1..100");
  if (!arguments.out.empty() && std::filesystem::path(arguments.out).extension() != ".json")
    throw demos::UsageError("--out " + arguments.out + ": must end in .json");
  TuneOptions options;
  options.max_error = arguments.max_error;
  if (arguments.metric == "final") {
    options.metric = TuneMetric::Final;
  } else if (arguments.metric == "trajectory") {
    options.metric = TuneMetric::Trajectory;
  } else {
    throw demos::UsageError("--metric '" + arguments.metric + "': expected final or trajectory");
  }
  options.duration = arguments.duration
                         ? *arguments.duration
                         : static_cast<double>(scene.view.steps) * scene.settings.time_step;
  if (!(options.duration > 0.0 && options.duration <= 3600.0))
    throw demos::UsageError("--duration must be in (0, 3600] seconds");
  options.quick = arguments.quick;
  options.repeats = arguments.repeats;
  const TuneResult result = tune_scene(scene, params, options);

  char line[512];
  std::snprintf(line, sizeof line,
                "tune %s: %zu candidates, metric %s over %.3g s, bound %.4g m; reference %s "
                "(%.0f us/s)\n",
                scene.name.c_str(), result.candidates.size(), arguments.metric.c_str(),
                options.duration, options.max_error, method_label(result.reference.method).c_str(),
                result.reference.us_per_simulated_second);
  out << line;
  std::snprintf(line, sizeof line, "scene's own method %s: error %.4g m, %.0f us/s\n",
                method_label(result.scene_default.method).c_str(), result.scene_default.error,
                result.scene_default.us_per_simulated_second);
  out << line;
  if (!result.found) {
    out << "no candidate stays within " << options.max_error
        << " m of the reference: keep the scene's method or loosen --max-error\n";
    if (!arguments.out.empty()) {
      char record[600];
      std::snprintf(record, sizeof record,
                    "{\n\"scene\": \"%s\", \"max_error\": %.6g, \"metric\": \"%s\", "
                    "\"duration\": %.6g, \"found\": false,\n\"scene_own_method\": \"%s\", "
                    "\"scene_own_error\": %.6g, \"candidates\": %zu\n}\n",
                    scene.name.c_str(), options.max_error, arguments.metric.c_str(),
                    options.duration, method_label(result.scene_default.method).c_str(),
                    result.scene_default.error, result.candidates.size());
      write_file_atomically(arguments.out, record);
      out << "wrote " << arguments.out << "\n";
    }
    return;
  }
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
  out << line << "{\n" << tuned_settings_json(result.chosen.method, scene.model) << "\n}\n";
  if (!arguments.out.empty()) {
    char figures[600];
    std::snprintf(figures, sizeof figures,
                  "{\n\"scene\": \"%s\", \"max_error\": %.6g, \"metric\": \"%s\", "
                  "\"duration\": %.6g, \"found\": true,\n\"method\": \"%s\", \"error\": %.6g, "
                  "\"us_per_simulated_second\": %.6g,\n\"scene_own_method\": \"%s\", "
                  "\"scene_own_error\": %.6g, \"scene_own_us_per_simulated_second\": %.6g,\n"
                  "\"reference_method\": \"%s\", \"reference_us_per_simulated_second\": %.6g,\n",
                  scene.name.c_str(), options.max_error, arguments.metric.c_str(), options.duration,
                  method_label(result.chosen.method).c_str(), result.chosen.error,
                  result.chosen.us_per_simulated_second,
                  method_label(result.scene_default.method).c_str(), result.scene_default.error,
                  result.scene_default.us_per_simulated_second,
                  method_label(result.reference.method).c_str(),
                  result.reference.us_per_simulated_second);
    write_file_atomically(arguments.out, figures + tuned_settings_json(result.chosen.method, scene.model) + "\n}\n");
    out << "wrote " << arguments.out << "\n";
  }
}

}  // namespace impulse2d::lab

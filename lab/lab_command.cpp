/// @file lab_command.cpp
/// `impulse2d lab` and `impulse2d lab merge` (tune: tune_command.cpp).
#include "lab/lab_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "frames/progress.h"
#include "image/file_io.h"
#include "lab/gnuplot.h"
#include "lab/lab_chart.h"
#include "lab/lab_output.h"
#include "lab/lab_peers.h"
#include "lab/lab_sweep.h"
#include "lab/option_numbers.h"
#include "lab/stability_map.h"
#include "lab/work_budget.h"
#include "scene/interrupt.h"
#include "scene/usage_error.h"
#include "scene/user_file.h"

namespace impulse2d::lab {
namespace {

namespace fs = std::filesystem;

/// A shard CSV as `lab merge` reads it.
const demos::UserFileKind lab_csv{"lab CSV", "a CSV file written by `impulse2d lab`",
                                  64u * 1024 * 1024, "64 MiB"};

/// Steps timed per scenario to estimate the sweep's minutes.
constexpr int probe_steps = 20;

/// Everything `lab` checked and decided before any work.
struct LabPlan {
  int shard_index = 1;                  ///< K of --shard K/N
  int shard_count = 1;                  ///< N
  int repeats = 3;                      ///< timed repeats per configuration
  std::vector<LabScenario> scenarios;   ///< the selected scenarios
  std::int64_t configurations = 0;      ///< configurations of this shard
  WorkEstimate sweep;                   ///< the sweep's work (empty with --no-sweep)
  bool stability = false;               ///< the stability map runs (only unsharded)
  bool charts = false;                  ///< charts are drawn (gnuplot found, unsharded)
  std::string csv_name;                 ///< "lab.csv" or "lab_shard_K_of_N.csv"
  std::vector<std::string> own_files;   ///< entries of --out this run writes
  std::vector<std::string> replaced;    ///< other runs' results --clean replaces
};

std::string results_csv(const std::vector<LabResult>& results) {
  std::string text = csv_header() + "\n";
  for (const LabResult& result : results) text += csv_line(result) + "\n";
  return text;
}

/// Seconds one step of `scenario` takes with the default method, from `probe_steps` steps.
double seconds_per_step(const LabScenario& scenario) {
  const std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, LabMethod{});
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < probe_steps; ++step) simulation->step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / probe_steps;
}

/// Parses, loads and checks everything `lab` needs; throws `demos::UsageError` before any work.
LabPlan make_lab_plan(const LabArguments& arguments) {
  LabPlan plan;
  std::tie(plan.shard_index, plan.shard_count) = parse_shard(arguments.shard);
  plan.repeats = arguments.repeats.empty() ? (arguments.quick ? 2 : 3)
                                           : static_cast<int>(count_option("--repeats", arguments.repeats, 1, 100));
  if (!arguments.sweep && !arguments.stability) {
    throw demos::UsageError("--no-sweep with --no-stability leaves nothing to run");
  }
  const std::string directory =
      arguments.scenarios.empty() ? default_scenario_directory() : arguments.scenarios;
  if (arguments.workers < 1 || arguments.workers > 64) {
    throw demos::UsageError("--workers " + std::to_string(arguments.workers) + ": must be 1..64");
  }
  plan.scenarios = load_lab_scenarios(directory);
  for (LabScenario& scenario : plan.scenarios) scenario.scene.settings.worker_count = arguments.workers;
  if (!arguments.only.empty()) {
    std::vector<LabScenario> chosen;
    for (const std::string& name : arguments.only) {
      const auto found = std::find_if(plan.scenarios.begin(), plan.scenarios.end(),
                                      [&](const LabScenario& scenario) { return scenario.name == name; });
      if (found == plan.scenarios.end()) {
        throw demos::UsageError("--only " + name + ": no such scenario in " + directory);
      }
      chosen.push_back(*found);
    }
    plan.scenarios = chosen;
  }
  const bool sharded = plan.shard_count > 1;
  plan.stability = arguments.stability && !sharded;
  plan.charts = arguments.charts && !sharded && gnuplot_available();
  plan.csv_name = sharded ? "lab_shard_" + std::to_string(plan.shard_index) + "_of_" +
                                std::to_string(plan.shard_count) + ".csv"
                          : "lab.csv";
  if (arguments.sweep) {
    plan.own_files.push_back(plan.csv_name);
    if (plan.charts) plan.own_files.push_back("charts");
    std::int64_t index = 0;
    for (const LabScenario& scenario : plan.scenarios) {
      const double probe = seconds_per_step(scenario);
      for (const LabMethod& method : sweep_methods(scenario, arguments.quick, arguments.peers)) {
        if (index++ % plan.shard_count != plan.shard_index - 1) continue;
        const std::int64_t steps = std::llround(scenario.duration / method.time_step);
        ++plan.configurations;
        plan.sweep.runs += plan.repeats;
        plan.sweep.steps += steps * plan.repeats;
        plan.sweep.seconds += probe * static_cast<double>(steps * plan.repeats);
      }
    }
  }
  if (plan.stability) {
    for (const char* name : {"stability.csv", "stability.png", "stability_sheets"}) {
      if (plan.charts || std::string(name) == "stability.csv") plan.own_files.push_back(name);
    }
  }
  const fs::path out(arguments.out);
  plan.replaced = other_runs_results(out, plan.own_files, plan.shard_count);
  check_output_directory(out, plan.replaced, arguments.clean, "--out");
  check_budget("lab", plan.sweep, plan.sweep.runs, max_lab_runs, "runs", arguments.force,
               "fewer --repeats, --only, --shard or --quick");
  return plan;
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

/// Says once that charts are skipped when gnuplot is missing.
void note_missing_gnuplot(bool charts_asked) {
  if (charts_asked && !gnuplot_available()) {
    std::fprintf(stderr,
                 "impulse2d lab: gnuplot not found: charts skipped (apt-get install gnuplot-nox)\n");
  }
}

/// A progress bar on stderr that appears with the first report (none when `quiet`).
class ProgressReport {
 public:
  ProgressReport(std::string label, std::string unit, bool quiet)
      : label_(std::move(label)), unit_(std::move(unit)), quiet_(quiet) {}
  /// `done` of `total` units finished.
  void update(std::int64_t done, std::int64_t total) {
    if (quiet_) return;
    if (!bar_ || total != total_) {
      bar_ = std::make_unique<demos::Progress>(label_, total, stderr, demos::is_terminal(stderr), unit_);
      total_ = total;
    }
    bar_->update(done);
  }
  /// Ends the bar.
  void finish() {
    if (bar_) bar_->finish();
  }

 private:
  std::string label_, unit_;
  bool quiet_;
  std::int64_t total_ = 0;
  std::unique_ptr<demos::Progress> bar_;
};

/// Runs the stability map into `staging`; writes stability.csv, stability.png and boundary
/// contact sheets; reports them under `shown` (the output folder).
void run_stability(const LabArguments& arguments, const LabPlan& plan, const fs::path& staging,
                   const std::string& shown, std::ostream& out) {
  const std::vector<Stressor> list = stressors(arguments.quick);
  const std::vector<LabMethod> methods = stability_methods(arguments.quick);
  ProgressReport bar("stability map", "cells", arguments.quiet);
  const std::vector<StabilityCell> cells = run_stability_map(
      list, methods, arguments.quick ? 0 : 4, [&](int done, int total) { bar.update(done, total); });
  bar.finish();
  image::write_text_file_atomically(staging / "stability.csv", stability_csv(cells));
  out << "wrote the stability map (" << methods.size() << " methods x " << list.size()
      << " stressors) to " << shown << "/stability.csv\n";
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
  if (!plan.charts) return;
  draw_stability_heat_map(cells, list, (staging / "stability.png").string());
  out << "wrote " << shown << "/stability.png\n";
  // Contact sheets of a few boundaries: the final frame on each side.
  // (Only cells with a boundary are drawn: a method that passes a whole ladder has none.)
  const std::string standard = method_label(LabMethod{});
  const std::string accumulated = method_label(method_for(SolverMethod::Accumulated));
  const std::vector<std::pair<std::string, std::string>> boundaries = {
      {standard, "stack_height"},   {standard, "time_step"},
      {standard, "friction_angle"}, {standard, "elastic_pile"},
      {standard + " noccd nospec", "bullet_speed"}, {accumulated, "elastic_pile"}};
  for (const auto& [label, stressor_name] : boundaries) {
    for (const StabilityCell& cell : cells) {
      if (method_label(cell.method) != label || cell.stressor != stressor_name) continue;
      if (!cell.any_pass || cell.all_pass || cell.method.engine != Engine::Impulse2d) continue;
      for (const Stressor& stressor : list) {
        if (stressor.name != stressor_name) continue;
        std::string file = label + "_" + stressor_name;
        for (char& c : file) c = (c == ' ' || c == '/') ? '_' : c;
        const std::string name = "stability_sheets/" + file + ".png";
        fs::create_directories(staging / "stability_sheets");
        demos::check_interrupt();
        draw_boundary_sheet(stressor, cell, (staging / name).string());
        out << "wrote " << shown << "/" << name << "\n";
      }
    }
  }
}

/// `interrupted` worded for a user of `command`: nothing was written, `folder` is as it was.
demos::Interrupted nothing_written(const std::string& command, const std::string& folder,
                                   const demos::Interrupted& interrupted) {
  return demos::Interrupted(interrupted.signal_number(),
                            command + " interrupted by " + demos::signal_name(interrupted.signal_number()) +
                                ": nothing written, " + folder + " is as it was");
}

/// Runs `plan_work` (which steps scenes to estimate the work, so a signal may stop it) and
/// returns its plan; a signal says that nothing was written, as one during the work does.
template <typename PlanWork>
auto planned(const std::string& command, const std::string& folder, PlanWork plan_work) {
  try {
    return plan_work();
  } catch (const demos::Interrupted& interrupted) {
    throw nothing_written(command, folder, interrupted);
  }
}

/// Runs `work` writing into `output`'s staging folder and commits it. A signal becomes an
/// `Interrupted` saying the folder is as it was; another failure names the files in the output
/// folder's terms.
template <typename Work>
void as_one_unit(const std::string& command, const std::string& folder, OutputTransaction& output,
                 Work work) {
  try {
    work();
    output.commit();
  } catch (const demos::Interrupted& interrupted) {
    throw nothing_written(command, folder, interrupted);
  } catch (const demos::UsageError&) {
    throw;
  } catch (const std::exception& error) {
    throw std::runtime_error(output.in_output_terms(error.what()) + " (nothing written, " + folder +
                             " is as it was)");
  }
}

/// The lines of the plan that name the output.
void print_output_plan(const std::string& folder, const std::vector<std::string>& own_files,
                       const std::vector<std::string>& replaced, std::ostream& out) {
  out << "would write into " << folder << "/ (all or nothing):";
  for (const std::string& name : own_files) out << " " << name << (name.find('.') == std::string::npos ? "/" : "");
  out << "\n";
  if (!replaced.empty()) {
    out << "would replace (--clean):";
    for (const std::string& name : replaced) out << " " << name;
    out << "\n";
  }
}

/// Reads, joins and checks the shard CSVs of `lab merge`; returns the rows with fronts marked.
std::vector<LabResult> read_shards(const MergeArguments& arguments) {
  if (arguments.inputs.empty()) throw demos::UsageError("lab merge: give the shard CSV files to join");
  std::vector<LabResult> results;
  for (const std::string& input : arguments.inputs) {
    for (LabResult& row : parse_csv(demos::read_user_file(input, lab_csv), input)) results.push_back(row);
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
  return results;
}

/// The entries `lab merge` writes.
std::vector<std::string> merge_files(const MergeArguments& arguments) {
  std::vector<std::string> files = {"lab.csv"};
  if (arguments.charts && gnuplot_available()) files.push_back("charts");
  return files;
}

}  // namespace

void plan_lab(const LabArguments& arguments, std::ostream& out) {
  const LabPlan plan = make_lab_plan(arguments);
  if (arguments.sweep) {
    out << "lab: " << plan.scenarios.size() << " scenarios, " << grouped(plan.configurations)
        << " configurations x " << plan.repeats << " repeats"
        << (plan.shard_count > 1 ? " (shard " + arguments.shard + ")" : std::string()) << ": "
        << describe_work(plan.sweep) << "; the bound is " << grouped(max_lab_runs) << " runs"
        << (plan.sweep.runs > max_lab_runs ? " (--force)" : "") << "\n";
  }
  if (plan.stability) {
    out << "lab: the stability map, " << stability_methods(arguments.quick).size() << " methods x "
        << stressors(arguments.quick).size() << " stressors\n";
  }
  print_output_plan(arguments.out, plan.own_files, plan.replaced, out);
}

void run_lab(const LabArguments& arguments, std::ostream& out) {
  const LabPlan plan = planned("lab", arguments.out, [&] { return make_lab_plan(arguments); });
  for (const Engine peer : {Engine::Box2d, Engine::Chipmunk}) {
    const std::string note = engine_note(peer);
    if (arguments.peers && arguments.sweep && !note.empty()) {
      std::fprintf(stderr, "impulse2d lab: %s\n", note.c_str());
    }
  }
  note_missing_gnuplot(arguments.charts && plan.shard_count == 1);
  OutputTransaction output(arguments.out, plan.replaced);
  const fs::path staging = output.staging();
  as_one_unit("lab", arguments.out, output, [&] {
    if (arguments.sweep) {
      SweepOptions options;
      options.quick = arguments.quick;
      options.repeats = plan.repeats;
      options.shard_index = plan.shard_index - 1;
      options.shard_count = plan.shard_count;
      options.peers = arguments.peers;
      ProgressReport bar("lab sweep", "runs", arguments.quiet);
      options.progress = [&](std::int64_t done, std::int64_t total) { bar.update(done, total); };
      const auto start = std::chrono::steady_clock::now();
      const std::vector<LabResult> results = run_sweep(plan.scenarios, options);
      bar.finish();
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      image::write_text_file_atomically(staging / plan.csv_name, results_csv(results));
      out << "wrote " << results.size() << " rows (" << plan.scenarios.size() << " scenarios, "
          << plan.repeats << " interleaved repeats, " << static_cast<int>(seconds) << " s) to "
          << arguments.out << "/" << plan.csv_name << "\n";
      summarise(results, out);
      if (plan.charts) {
        const std::vector<std::string> charts = draw_lab_charts(results, (staging / "charts").string());
        out << "wrote " << charts.size() << " charts to " << arguments.out << "/charts/\n";
      }
    }
    if (plan.stability) run_stability(arguments, plan, staging, arguments.out, out);
  });
}

void plan_merge(const MergeArguments& arguments, std::ostream& out) {
  const std::vector<LabResult> results = read_shards(arguments);
  const std::vector<std::string> files = merge_files(arguments);
  const std::vector<std::string> replaced = other_runs_results(arguments.out, files, 0);
  check_output_directory(arguments.out, replaced, arguments.clean, "--out");
  out << "lab merge: " << arguments.inputs.size() << " files, " << results.size() << " rows\n";
  print_output_plan(arguments.out, files, replaced, out);
}

void merge_lab(const MergeArguments& arguments, std::ostream& out) {
  const std::vector<LabResult> results = read_shards(arguments);
  const std::vector<std::string> files = merge_files(arguments);
  const std::vector<std::string> replaced = other_runs_results(arguments.out, files, 0);
  check_output_directory(arguments.out, replaced, arguments.clean, "--out");
  note_missing_gnuplot(arguments.charts);
  OutputTransaction output(arguments.out, replaced);
  const fs::path staging = output.staging();
  as_one_unit("lab merge", arguments.out, output, [&] {
    image::write_text_file_atomically(staging / "lab.csv", results_csv(results));
    out << "merged " << arguments.inputs.size() << " files, " << results.size() << " rows into "
        << arguments.out << "/lab.csv\n";
    summarise(results, out);
    if (files.size() > 1) {
      const std::vector<std::string> charts = draw_lab_charts(results, (staging / "charts").string());
      out << "wrote " << charts.size() << " charts to " << arguments.out << "/charts/\n";
    }
  });
}

}  // namespace impulse2d::lab

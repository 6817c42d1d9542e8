/// @file command_lab.cpp
/// `impulse2d lab` (and `lab merge`): the speed-accuracy lab.
#include <CLI/CLI.hpp>
#include <memory>

#include "app/command.h"
#include "app/strict_number_check.h"
#include "lab/lab_command.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d lab` and `impulse2d lab merge`.
struct LabCommandArguments {
  lab::LabArguments lab;      ///< the sweep, peers, charts and stability map
  lab::MergeArguments merge;  ///< `lab merge`
};

}  // namespace

Command add_lab_command(CLI::App& program, const ProgramOptions& options) {
  auto arguments = std::make_shared<LabCommandArguments>();
  lab::LabArguments& lab_arguments = arguments->lab;
  CLI::App* command = program.add_subcommand(
      "lab",
      "the speed-accuracy lab: every method on scenarios with exact answers, peers, charts, "
      "stability map (CSV and PNG into --out, all or nothing)");
  command->add_flag("--quick", lab_arguments.quick,
                    "a smaller method space, 2 repeats and a short stability map (for CI)");
  command->add_option("--scenarios", lab_arguments.scenarios,
                      "directory of scenario files (default: the installed ones, "
                      "share/impulse2d/lab/scenarios beside bin/impulse2d, else the source "
                      "tree's lab/scenarios)");
  command->add_option("--only", lab_arguments.only, "run only these scenarios (names)")
      ->delimiter(',');
  command->add_option("--out,-o", lab_arguments.out, "output directory")->capture_default_str();
  command->add_option("--repeats", lab_arguments.repeats,
                      "timed repeats per configuration, interleaved, 1..100 (default 3; 2 with --quick)");
  command->add_option("--shard", lab_arguments.shard,
                      "K/N: run every N-th configuration starting at the K-th (join with `lab merge`)")
      ->capture_default_str();
  command->add_option("--workers", lab_arguments.workers,
                      "threads sharing each step of the sweep's scenarios, 1..64 (same results, "
                      "other timings)")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_flag("!--no-peers", lab_arguments.peers, "skip Box2D and Chipmunk");
  command->add_flag("!--no-charts", lab_arguments.charts, "write the CSVs only");
  command->add_flag("!--no-stability", lab_arguments.stability, "skip the stability map");
  command->add_flag("!--no-sweep", lab_arguments.sweep,
                    "skip the method sweep: run the stability map only");
  command->add_flag("--clean", lab_arguments.clean,
                    "replace the results of another lab run found in --out (else refused)");
  command->add_flag("--force", lab_arguments.force,
                    "run even when the estimated work exceeds the bound (20,000 runs)");
  lab::MergeArguments& merge_arguments = arguments->merge;
  CLI::App* merge = command->add_subcommand(
      "merge", "join shard CSVs of `lab --shard K/N` into one lab.csv and draw the charts");
  merge->add_option("inputs", merge_arguments.inputs, "shard CSV files")->required();
  merge->add_option("--out,-o", merge_arguments.out, "output directory")->capture_default_str();
  merge->add_flag("!--no-charts", merge_arguments.charts, "write the CSV only");
  merge->add_flag("--clean", merge_arguments.clean,
                  "replace the results of another lab run found in --out (else refused)");

  Command result;
  result.parser = command;
  result.dry_run = [arguments, merge](std::ostream& out) {
    if (merge->parsed()) {
      lab::plan_merge(arguments->merge, out);
    } else {
      lab::plan_lab(arguments->lab, out);
    }
  };
  result.run = [arguments, merge, &options](std::ostream& out) {
    std::ostream discard(nullptr);  // where --quiet sends the lab's summary lines
    std::ostream& summary = options.quiet ? discard : out;
    if (merge->parsed()) {
      lab::merge_lab(arguments->merge, summary);
    } else {
      arguments->lab.quiet = options.quiet;
      lab::run_lab(arguments->lab, summary);
    }
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos

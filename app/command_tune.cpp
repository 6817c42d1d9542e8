/// @file command_tune.cpp
/// `impulse2d tune`: the cheapest method within an error bound, as JSON settings.
#include <CLI/CLI.hpp>
#include <memory>

#include "app/command.h"
#include "lab/lab_command.h"

namespace impulse2d::demos {

Command add_tune_command(CLI::App& program, const ProgramOptions& options) {
  auto tune = std::make_shared<lab::TuneArguments>();
  CLI::App* command = program.add_subcommand(
      "tune",
      "find the cheapest method whose error against a tight reference run stays under "
      "--max-error; print it as JSON settings for the scene file");
  command->add_option("scene", tune->scene, "built-in scene name or a .json scene file")
      ->required();
  command->add_option("--param,-p", tune->params,
                      "scene parameter key=value, one per flag (repeatable)")
      ->allow_extra_args(false);
  command->add_option("--max-error", tune->max_error, "largest allowed error, metres, in (0, 1000]")
      ->required();
  command->add_option("--metric", tune->metric,
                      "final (largest body distance from the reference at the end) or "
                      "trajectory (largest over samples every 0.1 s)")
      ->capture_default_str();
  command->add_option("--duration", tune->duration,
                      "simulated seconds, in (0, 3600] (default: the scene's run)");
  command->add_flag("--quick", tune->quick, "a smaller search space");
  command->add_option("--repeats", tune->repeats, "timed repeats per candidate, 1..100")
      ->capture_default_str();
  command->add_option("--out,-o", tune->out,
                      "also write the answer and its figures to this .json file");
  command->add_flag("--force", tune->force,
                    "run even when the estimated work exceeds the bound (20,000,000 steps)");

  Command result;
  result.parser = command;
  result.dry_run = [tune](std::ostream& out) { lab::plan_tune(*tune, out); };
  result.run = [tune, &options](std::ostream& out) {
    tune->quiet = options.quiet;
    lab::run_tune(*tune, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos

/// @file command_golden.cpp
/// `impulse2d golden check|update|frame`: the golden images of JSON scene files.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <iostream>
#include <memory>
#include <string>

#include "app/command.h"
#include "app/state_file.h"
#include "app/strict_number_check.h"
#include "scene/usage_error.h"
#include "golden/scenes/golden_command.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d golden`: the library's arguments and the scene file of `golden frame`.
struct GoldenArguments {
  golden::GoldenCommandArguments command;  ///< what the golden command runs
  std::string frame_file;                  ///< `golden frame`'s scene file
  std::string load_state;                  ///< `golden frame`: start from this saved world
};

}  // namespace

Command add_golden_command(CLI::App& program, const ProgramOptions&) {
  auto golden = std::make_shared<GoldenArguments>();
  golden::GoldenCommandArguments& arguments = golden->command;
  CLI::App* command = program.add_subcommand(
      "golden",
      "golden images of JSON scene files with a \"golden\" block: check, update, frame");
  command->require_subcommand(1);
  CLI::App* check = command->add_subcommand(
      "check", "check every golden frame of the scene files (classified failures, report)");
  CLI::App* update = command->add_subcommand(
      "update", "write missing and failing goldens (each rendered in two processes first)");
  for (CLI::App* sub : {check, update}) {
    sub->add_option("files", arguments.files, "scene files (.json)")->required();
    sub->add_option("--report", arguments.report_dir,
                    "artifacts and index.html of this run (emptied first)")
        ->capture_default_str();
    sub->add_option("--junit", arguments.junit, "also write JUnit XML to this file");
  }
  check->add_option("--repeat", arguments.repeat,
                    "2: also render each frame in a second process (nondeterminism)")
      ->capture_default_str();
  check->add_flag("--require-pixels", arguments.require_pixels,
                  "a frame whose renderer has no baseline fails (else: physics only)");
  update->add_flag("--all", arguments.all, "rewrite every golden, not only failing");
  CLI::App* frame = command->add_subcommand(
      "frame", "render one golden frame into --out PNG and its state hash into PNG.hash");
  frame->add_option("file", golden->frame_file, "scene file (.json)")->required();
  frame->add_option("name", arguments.frame, "golden frame name")->required();
  frame->add_option("--out,-o", arguments.out, "PNG to write")->required();
  for (CLI::App* sub : {check, update, frame}) {
    sub->add_option("--workers", arguments.workers,
                    "threads sharing each physics step, 1..64 (frames and states are the same "
                    "for any count)")
        ->capture_default_str()
        ->check(whole_number_check());
  }
  frame->add_option("--load-state", golden->load_state,
                    "start from a world saved by `trace --save-state` of the same scene file "
                    "(the frame's step stays the golden's own; a state saved after it is refused)");

  Command result;
  result.parser = command;
  result.own_exit_status = true;  // `golden check`: 1 when a golden failed
  // The arguments as the library takes them, once the command line is parsed.
  auto chosen = [golden, check, update, frame]() -> golden::GoldenCommandArguments& {
    golden::GoldenCommandArguments& library_arguments = golden->command;
    library_arguments.action = check->parsed() ? "check" : update->parsed() ? "update" : "frame";
    if (frame->parsed()) library_arguments.files = {golden->frame_file};
    library_arguments.start_run = nullptr;
    if (frame->parsed() && !golden->load_state.empty()) {
      library_arguments.start_run = [file = golden->load_state](SceneRun& run,
                                                                std::int64_t frame_step) {
        load_state_file(file, run);
        if (run.step_count() > frame_step) {
          throw UsageError("--load-state " + file + ": saved after " +
                           std::to_string(run.step_count()) + " steps, past the golden frame's " +
                           std::to_string(frame_step) + " (save it at step " +
                           std::to_string(frame_step) + " or earlier)");
        }
      };
    }
    library_arguments.executable = "/proc/self/exe";  // this program, for the second process
    return library_arguments;
  };
  result.dry_run = [chosen](std::ostream& out) {
    try {
      golden::dry_run_golden_command(chosen(), out);
    } catch (const UsageError& error) {
      throw UsageError(std::string("golden: ") + error.what());
    }
  };
  result.run = [chosen](std::ostream& out) {
    return golden::run_golden_command(chosen(), out, std::cerr);
  };
  return result;
}

}  // namespace impulse2d::demos

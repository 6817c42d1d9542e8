/// @file cli.cpp
/// The program's parser: its own options (--help, --version, --quiet, --dry-run), the
/// subcommands (one file each, app/command_<name>.cpp), and the errors turned into messages
/// and exit statuses.
#include "app/cli.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.h"
#include "app/help_formatter.h"
#include "app/parse_error_message.h"
#include "demos/scene_registry.h"
#include "frames/version.h"
#include "render/offscreen_backend.h"
#include "render/render_error.h"
#include "scene/interrupt.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

constexpr int exit_runtime_error = 1;
constexpr int exit_usage_error = 2;

/// The exit statuses, the same for every command except `diff` (which follows cmp and diff).
const char* const exit_status_footer =
    "Exit status: 0 success; 1 runtime failure (unwritable output, renderer, ffmpeg; for "
    "`golden check`: a golden failed); 2 bad usage or invalid input (unknown command, option, "
    "scene or parameter, invalid scene file); 128+N stopped by signal N (130 for Ctrl-C).";

/// Flushes stdout and reports a failed write (a full disk): exit status 1 with the reason,
/// instead of 0 with the output cut. A reader that closed the pipe early (`impulse2d list |
/// head -1`) wanted no more: the program ends quietly with the status a program killed by
/// SIGPIPE has (128 + 13), as GNU tools do.
int check_standard_output() {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return 0;
  const int reason = errno;
  if (reason == EPIPE) return 128 + SIGPIPE;
  std::cerr << "impulse2d: error: writing to standard output failed: "
            << (reason != 0 ? std::strerror(reason) : "stream error") << "\n";
  return exit_runtime_error;
}

/// The offscreen renderer chosen by --backend, else by the environment. A bad one is bad
/// usage (exit 2), found before any work, not a renderer failure half-way.
void choose_backend(const std::string& backend) {
  try {
    render::set_default_backend(backend.empty() ? render::default_backend()
                                                : render::parse_backend(backend, "--backend"));
  } catch (const render::RenderError& error) {
    throw UsageError(error.what());
  }
}

/// `impulse2d help [COMMAND]` as the parser understands it: `--help` of the program or of
/// that command. Throws `UsageError` for an unknown command or more than one.
std::vector<std::string> help_as_flag(const std::vector<std::string>& arguments,
                                      const std::vector<Command>& commands) {
  if (arguments.size() == 1) return {"--help"};
  std::string names;
  for (const Command& command : commands) {
    const std::string& name = command.parser->get_name();
    if (arguments.size() == 2 && arguments[1] == name) return {name, "--help"};
    names += (names.empty() ? "" : ", ") + name;
  }
  if (arguments.size() > 2) {
    throw UsageError("help: one command at most (impulse2d help COMMAND), got " +
                     std::to_string(arguments.size() - 1) + " words");
  }
  throw UsageError("help: unknown command '" + arguments[1] + "' (commands: " + names + ")");
}

/// Runs the command the command line named (the default demo when none); returns the exit
/// status. Errors are thrown.
int run_command(const std::vector<Command>& commands, const ProgramOptions& options) {
  const Command* chosen = nullptr;
  for (const Command& command : commands) {
    if (command.parser->parsed()) chosen = &command;
  }
  if (chosen != nullptr && chosen->renders) choose_backend(options.backend);
  if (options.dry_run && chosen != nullptr) {
    if (chosen->dry_run) chosen->dry_run(std::cout);
    return check_standard_output();
  }
  if (chosen == nullptr) {
    render_default_demo(options, std::cout);
    return check_standard_output();
  }
  const int status = chosen->run(std::cout);
  if (chosen->own_exit_status) return status;
  return check_standard_output();
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{
      "impulse2d: a 2D impulse-based rigid-body engine; renders scenes to PNG frames.\n"
      "Without a command it renders the default demo (" +
          default_scene().name + ") into out/,\nwith the overlays " + default_demo_overlays +
          ".\n`impulse2d help COMMAND` (or COMMAND --help) lists a command's options.",
      "impulse2d"};
  // Set before the commands are added: each takes its parent's formatter.
  app.formatter(std::make_shared<HelpFormatter>());
  app.require_subcommand(0, 1);
  // Options of the program (--quiet, --version) may also come after the command's name.
  app.fallthrough();
  app.footer(exit_status_footer);
  app.set_version_flag("--version,-V", "impulse2d " + program_version(), "print the version and exit");
  ProgramOptions options;
  app.add_flag("--quiet,-q", options.quiet,
               "no progress and no summary lines (render, sheet, lab, lab merge); errors and "
               "warnings still print, and what a command is asked to print (list, trace, tune, "
               "diff, golden) still does");
  app.add_flag("--dry-run", options.dry_run,
               "make every check the command makes before any work (options, numbers, scene, "
               "parameters, --frames, camera, output folders) and print its plan: what would "
               "run and the files it would write; nothing runs, nothing is written");
  // In the order of the help's list.
  const std::vector<Command> commands = {
      add_list_command(app, options),  add_render_command(app, options),
      add_trace_command(app, options), add_sheet_command(app, options),
      add_diff_command(app, options),  add_golden_command(app, options),
      add_lab_command(app, options),   add_tune_command(app, options)};

  std::vector<std::string> arguments(argv + 1, argv + argc);
  if (!arguments.empty() && arguments.front() == "help") {
    try {
      arguments = help_as_flag(arguments, commands);
    } catch (const UsageError& error) {
      std::cerr << "impulse2d: " << error.what() << "\n";
      return exit_usage_error;
    }
  }
  try {
    // CLI11 parses a vector given in reverse order (and consumes it).
    std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());
    app.parse(reversed);
  } catch (const CLI::Success& done) {
    return app.exit(done);  // --help, --version
  } catch (const CLI::ParseError& error) {
    std::cerr << parse_error_message(app, error, arguments);
    return exit_usage_error;
  }

  // ffmpeg reading from a pipe may exit early; report that as an error, not a signal.
  std::signal(SIGPIPE, SIG_IGN);
  install_interrupt_handlers();
  try {
    return run_command(commands, options);
  } catch (const Interrupted& interrupted) {
    std::cerr << "impulse2d: " << interrupted.what() << "\n";
    return interrupted.exit_status();
  } catch (const UsageError& error) {
    std::cerr << "impulse2d: " << error.what() << "\n";
    return exit_usage_error;
  } catch (const std::exception& error) {
    std::cerr << "impulse2d: error: " << error.what() << "\n";
    return exit_runtime_error;
  }
}

}  // namespace impulse2d::demos

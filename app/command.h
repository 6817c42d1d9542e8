#pragma once
/// @file command.h
/// The subcommands of the `impulse2d` program, one file each (app/command_<name>.cpp): each
/// adds its options to the program's CLI11 parser and says how it runs; app/cli.cpp
/// assembles them, parses, and turns errors into messages and exit statuses.

#include <functional>
#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace impulse2d::demos {

/// The program's own options (before or after the command's name), read by the commands
/// once the command line is parsed.
struct ProgramOptions {
  bool quiet = false;    ///< --quiet: no progress and no summary lines
  bool dry_run = false;  ///< --dry-run: check the command line and stop
  std::string backend;   ///< --backend of render and sheet ("": $IMPULSE2D_BACKEND, else osmesa)
};

/// One subcommand added to the program's parser. Its arguments live as long as the lambdas.
struct Command {
  CLI::App* parser = nullptr;  ///< its CLI11 subcommand (`parsed()` when the command line named it)
  bool renders = false;        ///< draws frames: the backend is checked before anything runs
  /// With --dry-run: runs every check a real run makes before any work and writes the plan
  /// (what would run, the files it would write) to `out`; writes and runs nothing. Throws
  /// `UsageError` (or the run's other errors) exactly as the run would. Empty: the parser's
  /// checks only.
  std::function<void(std::ostream& out)> dry_run;
  /// Runs the command, writing its report to `out`; returns the exit status. Throws
  /// `UsageError` for bad input, `Interrupted` on a signal, other exceptions for failures.
  std::function<int(std::ostream& out)> run;
  /// The status `run` returns is the program's (diff and golden follow their own rules);
  /// otherwise a finished run exits 0 when standard output was written completely.
  bool own_exit_status = false;
};

/// `impulse2d list`.
Command add_list_command(CLI::App& program, const ProgramOptions& options);
/// `impulse2d render`.
Command add_render_command(CLI::App& program, ProgramOptions& options);
/// `impulse2d trace`.
Command add_trace_command(CLI::App& program, const ProgramOptions& options);
/// `impulse2d sheet`.
Command add_sheet_command(CLI::App& program, ProgramOptions& options);
/// `impulse2d diff`.
Command add_diff_command(CLI::App& program, const ProgramOptions& options);
/// `impulse2d golden check|update|frame`.
Command add_golden_command(CLI::App& program, const ProgramOptions& options);
/// `impulse2d lab` and `impulse2d lab merge`.
Command add_lab_command(CLI::App& program, const ProgramOptions& options);
/// `impulse2d tune`.
Command add_tune_command(CLI::App& program, const ProgramOptions& options);

/// The overlays of the default demo (`render <default scene> --overlays ...`).
inline constexpr const char* default_demo_overlays = "normals,impulses,penetration";

/// No command: renders the default demo into out/ (replacing its earlier frames there) with
/// `default_demo_overlays`, as `render <default scene> --overlays ... --clean` would; with
/// --dry-run, prints that render's plan instead.
void render_default_demo(const ProgramOptions& options, std::ostream& out);

}  // namespace impulse2d::demos

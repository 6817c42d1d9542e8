/// @file cli.cpp
#include "app/cli.h"

#include <CLI/CLI.hpp>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "lab/lab_command.h"
#include "app/commands.h"
#include "scene/interrupt.h"
#include "app/parse_error_message.h"
#include "frames/version.h"
#include "render/offscreen_backend.h"
#include "render/render_error.h"
#include "scene/overlays.h"
#include "demos/scene_registry.h"
#include "scene/usage_error.h"
#include "golden/diff_command.h"
#include "golden/diff_limits.h"
#include "golden/scenes/golden_command.h"

namespace impulse2d::demos {
namespace {

constexpr int exit_runtime_error = 1;
constexpr int exit_usage_error = 2;

std::string overlay_help() {
  std::string text = "comma-separated overlays (default: the scene's):";
  for (const OverlayName& each : overlay_names()) {
    text += std::string("\n  ") + each.name + ": " + each.description;
  }
  return text;
}

/// The exit statuses, the same for every command except `diff` (which follows cmp and diff).
const char* const exit_status_footer =
    "Exit status: 0 success; 1 runtime failure (unwritable output, renderer, ffmpeg; for "
    "`golden check`: a golden failed); 2 bad usage or invalid input (unknown command, option, "
    "scene or parameter, invalid scene file); 128+N stopped by signal N (130 for Ctrl-C).";

/// `--backend osmesa|egl` on a command that renders.
void add_backend_option(CLI::App& command, std::string& backend) {
  command.add_option("--backend", backend,
                     "offscreen renderer: osmesa or egl (default: $IMPULSE2D_BACKEND, else osmesa)")
      ->check(CLI::IsMember({"osmesa", "egl"}));
}

void add_scene_options(CLI::App& command, SceneArguments& arguments, bool scene_required) {
  CLI::Option* scene = command.add_option(
      "scene", arguments.scene, "built-in scene name (see `impulse2d list`) or a .json scene file");
  if (scene_required) scene->required();
  command.add_option("--param,-p", arguments.params,
                     "scene parameter key=value, one per flag (repeat it: -p rows=8 -p seed=3)")
      ->allow_extra_args(false);
  command.add_flag("--strict", arguments.strict,
                   "a body that diverges (non-finite state) is an error (exit 1), not a warning");
}

/// Flushes stdout and reports a failed write (a full disk, a closed pipe): exit status 1
/// with the reason, instead of 0 with the output cut.
int check_standard_output() {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return 0;
  const int reason = errno;
  std::cerr << "impulse2d: error: writing to standard output failed: "
            << (reason != 0 ? std::strerror(reason) : "stream error") << "\n";
  return exit_runtime_error;
}

}  // namespace

int run_cli(int argc, char** argv) {
  CLI::App app{
      "impulse2d: a 2D impulse-based rigid-body engine; renders scenes to PNG frames.\n"
      "Without a command it renders the default demo (" +
          default_scene().name + ") into out/.",
      "impulse2d"};
  app.require_subcommand(0, 1);
  // Options of the program (--quiet, --version) may also come after the command's name.
  app.fallthrough();
  app.footer(exit_status_footer);
  app.set_version_flag("--version", "impulse2d " + program_version(), "print the version and exit");
  bool quiet = false;
  app.add_flag("--quiet,-q", quiet,
               "no progress and no summary lines (render, sheet, lab, lab merge); errors and "
               "warnings still print, and what a command is asked to print (list, trace, tune, "
               "diff, golden) still does");
  bool dry_run = false;
  app.add_flag("--dry-run", dry_run,
               "check the command line and stop: options, values and, for render, trace and "
               "sheet, the scene, its parameters and --frames; nothing runs, nothing is written");

  std::string backend;
  CLI::App* list =
      app.add_subcommand("list", "list the built-in scenes with their parameters and models");

  RenderArguments render;
  CLI::App* render_command =
      app.add_subcommand("render", "render a scene into a PNG frame sequence");
  add_scene_options(*render_command, render.scene, true);
  add_backend_option(*render_command, backend);
  render_command->add_option(
      "--frames,-f", render.frames,
      "steps to draw: A:B[:k] ranges, comma-separated (step n = the world after n steps)");
  render_command->add_option("--steps", render.scene.steps,
                             "length of the run in steps (default: the scene's)");
  render_command->add_option("--size,-s", render.size, "frame size WxH in pixels")
      ->capture_default_str();
  render_command->add_option("--overlays", render.overlays, overlay_help());
  render_command->add_option("--theme", render.theme, "light or dark")->capture_default_str();
  render_command->add_option("--out,-o", render.out,
                             "output directory: <scene>_00000.png, <scene>_00001.png, ... (one "
                             "per frame, numbered from 0 whatever steps they show) and "
                             "<scene>_frames.csv (frame,step,time,file)")
      ->capture_default_str();
  render_command->add_option("--video", render.video,
                             "also write a video (.mp4, .webm or .gif; needs ffmpeg)");
  render_command->add_option("--fps", render.fps,
                             "video frames per second, 1..240 (default: real time)");
  render_command->add_flag("--no-frames", render.no_frames,
                           "write the --video only, no PNG frames");
  render_command->add_option("--threads", render.threads, "PNG encoding threads")
      ->capture_default_str();
  render_command->add_option("--trails", render.trails,
                             "motion trails: 'dynamic' (every dynamic body) or body indices "
                             "3,7,12 (as the ids overlay shows them)");
  render_command->add_flag("--html", render.html,
                           "also write <scene>.html beside the frames: a viewer for the browser "
                           "(scrubber, play/pause, step/time/energy/contacts, timeline) with an "
                           "overlay switch pre-rendered into <scene>.overlays/");
  render_command->add_flag("--clean", render.clean,
                           "replace frames of the same scene already in the output directory "
                           "(without it they are an error); done only when the run succeeds");
  add_view_options(*render_command, render.view, true);

  TraceArguments trace;
  CLI::App* trace_command = app.add_subcommand(
      "trace", "print per-step body states (step,t,body,x,y,angle,vx,vy,omega,contacts,energy)");
  add_scene_options(*trace_command, trace.scene, true);
  trace_command->add_option("--steps,-n", trace.scene.steps,
                            "steps to simulate (default: the scene's)");
  trace_command->add_option("--every,-k", trace.every, "sample every k-th step")
      ->capture_default_str();
  trace_command->add_option("--format", trace.format, "csv or json")->capture_default_str();

  SheetArguments sheet;
  CLI::App* sheet_command = app.add_subcommand(
      "sheet", "tile chosen frames of a run into one labelled PNG (a contact sheet)");
  add_scene_options(*sheet_command, sheet.scene, false);
  add_backend_option(*sheet_command, backend);
  sheet_command->add_option("--frames,-f", sheet.frames,
                            "steps to show: A:B[:k] ranges (default: --count spread)");
  sheet_command->add_option("--count,-c", sheet.count, "frames spread evenly over the run")
      ->capture_default_str();
  sheet_command->add_option("--steps", sheet.scene.steps,
                            "length of the run in steps (default: the scene's)");
  sheet_command->add_option("--columns", sheet.columns, "tiles per row")->capture_default_str();
  sheet_command->add_option("--tile", sheet.tile, "tile size WxH in pixels")->capture_default_str();
  sheet_command->add_option("--overlays", sheet.overlays, overlay_help());
  sheet_command->add_option("--theme", sheet.theme, "light or dark")->capture_default_str();
  sheet_command->add_option("--trails", sheet.trails,
                            "motion trails: 'dynamic' (every dynamic body) or body indices "
                            "3,7,12 (as the ids overlay shows them)");
  sheet_command->add_option("--out,-o", sheet.out,
                            "PNG file (default: out/contact_sheet_<scene>.png)");
  add_view_options(*sheet_command, sheet.view, false);

  std::string diff_expected, diff_actual, diff_out;
  CLI::App* diff_command = app.add_subcommand(
      "diff",
      "compare two PNG frames as the golden suite does (exact RGBA match first, metrics on a "
      "mismatch; the frames' metadata says whether the physics or only the pixels differ)");
  diff_command->footer(
      "Exit status (as cmp and diff): 0 the frames match, 1 they differ, 2 trouble (bad usage, "
      "an unreadable input, an unwritable --out).");
  diff_command->add_option("expected", diff_expected, "the reference PNG (a)")->required();
  diff_command->add_option("actual", diff_actual, "the PNG to check (b)")->required();
  diff_command->add_option("--out,-o", diff_out,
                           "on a mismatch, write expected/actual/diff/heatmap PNGs, "
                           "metrics.json and index.html into this directory");
  golden::DiffLimits diff_limits;
  diff_command->add_option("--max-diff-pixels", diff_limits.max_diff_pixels,
                           "pass when at most this many pixels differ (default: none may)");
  diff_command->add_option("--max-diff-ratio", diff_limits.max_diff_ratio,
                           "pass when at most this fraction (0..1) of pixels differs");
  diff_command->add_option("--threshold", diff_limits.threshold,
                           "a pixel differs when a channel changes by more than this (0..255)")
      ->capture_default_str();
  diff_command->add_option("--mask", diff_limits.masks,
                           "x,y,w,h: ignore this rectangle (pixels from the top-left; "
                           "one rectangle per flag, repeatable)")
      ->take_all()
      ->allow_extra_args(false);

  golden::GoldenCommandArguments golden_arguments;
  CLI::App* golden_command = app.add_subcommand(
      "golden",
      "golden images of JSON scene files with a \"golden\" block: check, update, frame");
  golden_command->require_subcommand(1);
  CLI::App* golden_check = golden_command->add_subcommand(
      "check", "check every golden frame of the scene files (classified failures, report)");
  CLI::App* golden_update = golden_command->add_subcommand(
      "update", "write missing and failing goldens (each rendered in two processes first)");
  for (CLI::App* sub : {golden_check, golden_update}) {
    sub->add_option("files", golden_arguments.files, "scene files (.json)")->required();
    sub->add_option("--report", golden_arguments.report_dir,
                    "artifacts and index.html of this run (emptied first)")
        ->capture_default_str();
    sub->add_option("--junit", golden_arguments.junit, "also write JUnit XML to this file");
  }
  golden_check->add_option("--repeat", golden_arguments.repeat,
                           "2: also render each frame in a second process (nondeterminism)")
      ->capture_default_str();
  golden_update->add_flag("--all", golden_arguments.all, "rewrite every golden, not only failing");
  CLI::App* golden_frame = golden_command->add_subcommand(
      "frame", "render one golden frame into --out PNG and its state hash into PNG.hash");
  std::string golden_frame_file;
  golden_frame->add_option("file", golden_frame_file, "scene file (.json)")->required();
  golden_frame->add_option("name", golden_arguments.frame, "golden frame name")->required();
  golden_frame->add_option("--out,-o", golden_arguments.out, "PNG to write")->required();

  lab::LabArguments lab_arguments;
  CLI::App* lab_command = app.add_subcommand(
      "lab",
      "the speed-accuracy lab: every method on scenarios with exact answers, peers, charts, "
      "stability map (CSV and PNG into --out)");
  lab_command->add_flag("--quick", lab_arguments.quick,
                        "a smaller method space, 2 repeats and a short stability map (for CI)");
  lab_command->add_option("--scenarios", lab_arguments.scenarios,
                          "directory of scenario files (default: the source tree's lab/scenarios)");
  lab_command->add_option("--only", lab_arguments.only, "run only these scenarios (names)")
      ->delimiter(',');
  lab_command->add_option("--out,-o", lab_arguments.out, "output directory")->capture_default_str();
  lab_command->add_option("--repeats", lab_arguments.repeats,
                          "timed repeats per configuration, interleaved (default 3; 2 with --quick)");
  lab_command->add_option("--shard", lab_arguments.shard,
                          "K/N: run every N-th configuration starting at the K-th (join with `lab merge`)")
      ->capture_default_str();
  lab_command->add_flag("!--no-peers", lab_arguments.peers, "skip Box2D and Chipmunk");
  lab_command->add_flag("!--no-charts", lab_arguments.charts, "write the CSVs only");
  lab_command->add_flag("!--no-stability", lab_arguments.stability, "skip the stability map");
  lab_command->add_flag("!--no-sweep", lab_arguments.sweep,
                        "skip the method sweep: run the stability map only");
  lab::MergeArguments merge_arguments;
  CLI::App* merge_command = lab_command->add_subcommand(
      "merge", "join shard CSVs of `lab --shard K/N` into one lab.csv and draw the charts");
  merge_command->add_option("inputs", merge_arguments.inputs, "shard CSV files")->required();
  merge_command->add_option("--out,-o", merge_arguments.out, "output directory")
      ->capture_default_str();
  merge_command->add_flag("!--no-charts", merge_arguments.charts, "write the CSV only");

  lab::TuneArguments tune_arguments;
  CLI::App* tune_command = app.add_subcommand(
      "tune",
      "find the cheapest method whose error against a tight reference run stays under "
      "--max-error; print it as JSON settings for the scene file");
  tune_command->add_option("scene", tune_arguments.scene,
                           "built-in scene name or a .json scene file")->required();
  tune_command->add_option("--param,-p", tune_arguments.params,
                           "scene parameter key=value, one per flag (repeatable)")
      ->allow_extra_args(false);
  tune_command->add_option("--max-error", tune_arguments.max_error,
                           "largest allowed error, metres")->required();
  tune_command->add_option("--metric", tune_arguments.metric,
                           "final (largest body distance from the reference at the end) or "
                           "trajectory (largest over samples every 0.1 s)")
      ->capture_default_str();
  tune_command->add_option("--duration", tune_arguments.duration,
                           "simulated seconds (default: the scene's run)");
  tune_command->add_flag("--quick", tune_arguments.quick, "a smaller search space");
  tune_command->add_option("--repeats", tune_arguments.repeats, "timed repeats per candidate")
      ->capture_default_str();
  tune_command->add_option("--out,-o", tune_arguments.out,
                           "also write the answer and its figures to this .json file");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& done) {
    return app.exit(done);  // --help, --version
  } catch (const CLI::ParseError& error) {
    std::cerr << parse_error_message(app, error, std::vector<std::string>(argv + 1, argv + argc));
    return exit_usage_error;
  }
  render.quiet = quiet;
  sheet.quiet = quiet;
  lab_arguments.quiet = quiet;
  std::ostream discard(nullptr);  // where --quiet sends the lab's summary lines
  std::ostream& summary = quiet ? discard : std::cout;

  // ffmpeg reading from a pipe may exit early; report that as an error, not a signal.
  std::signal(SIGPIPE, SIG_IGN);
  install_interrupt_handlers();
  try {
    if (render_command->parsed() || sheet_command->parsed()) {
      // The backend (option, else environment) is checked before any work: a bad one is
      // bad usage (exit 2), not a renderer failure half-way.
      try {
        render::set_default_backend(backend.empty() ? render::default_backend()
                                                    : render::parse_backend(backend, "--backend"));
      } catch (const render::RenderError& error) {
        throw UsageError(error.what());
      }
    }
    if (dry_run) {
      if (render_command->parsed()) check_scene_arguments(render.scene, render.frames);
      if (trace_command->parsed()) check_scene_arguments(trace.scene, std::nullopt);
      if (sheet_command->parsed()) check_scene_arguments(sheet.scene, sheet.frames);
      return 0;
    }
    if (list->parsed()) {
      list_scenes(std::cout);
    } else if (render_command->parsed()) {
      render_scene(render, std::cout);
    } else if (trace_command->parsed()) {
      trace_scene(trace, std::cout);
    } else if (sheet_command->parsed()) {
      sheet_scene(sheet, std::cout);
    } else if (merge_command->parsed()) {
      lab::merge_lab(merge_arguments, summary);
    } else if (lab_command->parsed()) {
      lab::run_lab(lab_arguments, summary);
    } else if (tune_command->parsed()) {
      lab::run_tune(tune_arguments, std::cout);
    } else if (golden_command->parsed()) {
      golden_arguments.action = golden_check->parsed()    ? "check"
                                : golden_update->parsed() ? "update"
                                                          : "frame";
      if (golden_frame->parsed()) golden_arguments.files = {golden_frame_file};
      golden_arguments.executable = "/proc/self/exe";  // this program, for the second process
      return golden::run_golden_command(golden_arguments, std::cout, std::cerr);
    } else if (diff_command->parsed()) {
      return golden::run_diff_command(diff_expected, diff_actual, diff_out, std::cout, std::cerr,
                                      diff_limits);
    } else {
      RenderArguments demo;
      demo.quiet = quiet;
      demo.scene.scene = default_scene().name;
      demo.clean = true;  // the default demo always refreshes out/<default scene>_*.png
      render_scene(demo, std::cout);
    }
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
  return check_standard_output();
}

}  // namespace impulse2d::demos

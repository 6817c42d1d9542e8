/// @file command_sheet.cpp
/// `impulse2d sheet`: chosen frames of a run tiled into one labelled PNG (a contact sheet).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <memory>

#include "app/command.h"
#include "app/scene_command.h"
#include "app/strict_number_check.h"
#include "app/view_options.h"
#include "demos/scene_registry.h"
#include "frames/contact_sheet.h"
#include "frames/frame_plan.h"
#include "frames/output_folder.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d sheet`.
struct SheetArguments {
  SceneArguments scene;                 ///< what to run
  std::optional<std::string> frames;    ///< `A:B:k` ranges; `count` evenly spread when absent
  int count = 8;                        ///< frames when `frames` is absent
  int columns = 4;                      ///< tiles per row
  std::string tile = "400x300";         ///< WxH pixels per tile
  std::optional<std::string> overlays;  ///< overlay list; the scene's default when absent
  std::string theme = "light";          ///< light or dark
  std::optional<std::string> out;       ///< PNG path; out/contact_sheet_<scene>.png when absent
  std::optional<std::string> trails;    ///< `dynamic` or body indices with motion trails
  ViewArguments view;                   ///< legend, scales, camera, highlight
};

/// A contact sheet, checked and ready: what `sheet_scene` runs and `print_sheet_plan` shows.
struct SheetJob {
  ResolvedScene resolved;          ///< the scene, its parameters and length
  FramePlan plan;                  ///< the steps shown
  ContactSheetOptions options;     ///< layout and looks
  std::filesystem::path output;    ///< the PNG
  std::pair<int, int> size;        ///< the sheet's width and height, pixels
  std::unique_ptr<SceneRun> run;   ///< the run, built and not yet stepped
};

/// Every check a contact sheet makes before any work; the run and --dry-run both start here.
/// Throws `UsageError` for bad input, `std::runtime_error` for an unwritable --out folder.
SheetJob prepare_sheet(const SheetArguments& arguments) {
  SheetJob job;
  SceneArguments scene_arguments = arguments.scene;
  if (scene_arguments.scene.empty()) scene_arguments.scene = default_scene().name;
  job.resolved = resolve(scene_arguments);
  ResolvedScene& resolved = job.resolved;
  apply_view_arguments(arguments.view, resolved.scene);
  if (arguments.count < 1 || arguments.count > 256) {
    throw UsageError("--count " + std::to_string(arguments.count) + ": must be 1..256");
  }
  job.plan = arguments.frames ? plan_frames(*arguments.frames, resolved.steps)
                              : spread_frames(arguments.count, resolved.steps);
  ContactSheetOptions& options = job.options;
  std::tie(options.tile_width, options.tile_height) = parse_size(arguments.tile, "--tile");
  if (arguments.columns < 1) {
    throw UsageError("--columns " + std::to_string(arguments.columns) + ": must be at least 1");
  }
  options.columns = arguments.columns;
  options.draw = resolved.scene.view.draw;
  if (arguments.overlays) options.draw.flags = parse_overlays_option(*arguments.overlays);
  options.theme = theme_of(arguments.theme);
  if (arguments.trails) options.trails = parse_trails(*arguments.trails, "--trails");
  options.caption = (resolved.params.specs().empty() ? "no parameters" : resolved.params.summary()) +
                    "  |  overlays: " + overlay_list(options.draw.flags);
  if (arguments.trails) options.caption += "  |  trails: " + *arguments.trails;
  job.size = contact_sheet_size(static_cast<int>(job.plan.frames.size()), options);
  job.output = arguments.out
                   ? std::filesystem::path(*arguments.out)
                   : std::filesystem::path("out") / ("contact_sheet_" + resolved.scene.name + ".png");
  if (job.output.extension() != ".png") {
    throw UsageError("--out " + job.output.string() + ": must end in .png");
  }

  job.run = start_run(resolved, scene_arguments);
  check_trails(options.trails, *job.run, "--trails");
  check_view_bodies(arguments.view, *job.run);
  check_camera(arguments.view, *job.run, options.tile_width, options.tile_height);
  check_output_folder(job.output.parent_path(), "--out " + job.output.string());
  return job;
}

/// What `sheet` would do, for --dry-run.
void print_sheet_plan(const SheetJob& job, std::ostream& out) {
  out << "dry run: sheet " << job.resolved.scene.name << " (" << job.resolved.scene.source << ")\n"
      << "  parameters: "
      << (job.resolved.params.specs().empty() ? "none" : job.resolved.params.summary()) << "\n"
      << "  steps: " << job.plan.steps << " of " << job.resolved.steps << "\n"
      << "  frames: " << job.plan.frames.size() << ": " << describe_frame_steps(job.plan) << "\n"
      << "  tiles: " << job.options.tile_width << "x" << job.options.tile_height << " in "
      << std::min<std::size_t>(static_cast<std::size_t>(job.options.columns), job.plan.frames.size())
      << " columns, overlays: " << overlay_list(job.options.draw.flags) << ", theme "
      << render::theme_name(job.options.theme) << "\n"
      << "  writes: " << job.output.string() << " (" << job.size.first << "x" << job.size.second
      << " pixels)\n"
      << "nothing was run or written\n";
}

/// Writes the contact sheet of `job`; prints where it went unless `quiet`.
void sheet_scene(SheetJob& job, bool quiet, std::ostream& out) {
  const auto [width, height] = write_contact_sheet(*job.run, job.plan, job.options, job.output);
  warn_divergences(*job.run);
  if (quiet) return;
  out << "wrote a " << width << "x" << height << " contact sheet of " << job.plan.frames.size()
      << " frames of " << job.resolved.scene.name << " to " << job.output.string() << "\n";
}

}  // namespace

Command add_sheet_command(CLI::App& program, ProgramOptions& options) {
  auto sheet = std::make_shared<SheetArguments>();
  CLI::App* command = program.add_subcommand(
      "sheet", "tile chosen frames of a run into one labelled PNG (a contact sheet)");
  add_scene_options(*command, sheet->scene, false);
  add_backend_option(*command, options.backend);
  command->add_option("--frames,-f", sheet->frames,
                      "steps to show: A:B[:k] ranges (default: --count spread)");
  command->add_option("--count,-c", sheet->count, "frames spread evenly over the run, 1..256")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_option("--steps", sheet->scene.steps,
                      "length of the run in steps (default: the scene's)")
      ->check(whole_number_check());
  command->add_option("--columns", sheet->columns, "tiles per row")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_option("--tile", sheet->tile, "tile size WxH in pixels, each side 16..8192")
      ->capture_default_str();
  command->add_option("--overlays", sheet->overlays, overlay_help());
  command->add_option("--theme", sheet->theme, "light or dark")->capture_default_str();
  command->add_option("--trails", sheet->trails,
                      "motion trails: 'dynamic' (every dynamic body) or body indices "
                      "3,7,12 (as the ids overlay shows them)");
  command->add_option("--out,-o", sheet->out, "PNG file (default: out/contact_sheet_<scene>.png)");
  add_view_options(*command, sheet->view, false);

  Command result;
  result.parser = command;
  result.renders = true;
  result.dry_run = [sheet](std::ostream& out) { print_sheet_plan(prepare_sheet(*sheet), out); };
  result.run = [sheet, &options](std::ostream& out) {
    SheetJob job = prepare_sheet(*sheet);
    sheet_scene(job, options.quiet, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos

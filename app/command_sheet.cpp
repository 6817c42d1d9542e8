/// @file command_sheet.cpp
/// `impulse2d sheet`: chosen frames of a run tiled into one labelled PNG (a contact sheet).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <memory>

#include "app/command.h"
#include "app/scene_command.h"
#include "app/view_options.h"
#include "demos/scene_registry.h"
#include "frames/contact_sheet.h"
#include "frames/frame_plan.h"
#include "scene/overlays.h"
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
  bool quiet = false;                   ///< no summary line
  ViewArguments view;                   ///< legend, scales, camera, highlight
};

/// Writes a contact sheet; prints where it went unless `arguments.quiet`.
void sheet_scene(const SheetArguments& arguments, std::ostream& out) {
  SceneArguments scene_arguments = arguments.scene;
  if (scene_arguments.scene.empty()) scene_arguments.scene = default_scene().name;
  ResolvedScene resolved = resolve(scene_arguments);
  apply_view_arguments(arguments.view, resolved.scene);
  if (arguments.count < 1 || arguments.count > 256) throw UsageError("--count must be 1..256");
  const FramePlan plan = arguments.frames ? plan_frames(*arguments.frames, resolved.steps)
                                          : spread_frames(arguments.count, resolved.steps);
  ContactSheetOptions options;
  std::tie(options.tile_width, options.tile_height) = parse_size(arguments.tile, "--tile");
  options.columns = arguments.columns;
  options.draw = resolved.scene.view.draw;
  if (arguments.overlays) options.draw.flags = parse_overlays(*arguments.overlays);
  options.theme = theme_of(arguments.theme);
  if (arguments.trails) options.trails = parse_trails(*arguments.trails, "--trails");
  options.caption = (resolved.params.specs().empty() ? "no parameters" : resolved.params.summary()) +
                    "  |  overlays: " + overlay_list(options.draw.flags);
  if (arguments.trails) options.caption += "  |  trails: " + *arguments.trails;
  // Refused before the scene runs or anything renders.
  contact_sheet_size(static_cast<int>(plan.frames.size()), options);
  const std::filesystem::path output =
      arguments.out
          ? std::filesystem::path(*arguments.out)
          : std::filesystem::path("out") / ("contact_sheet_" + resolved.scene.name + ".png");
  if (output.extension() != ".png")
    throw UsageError("--out " + output.string() + ": must end in .png");

  const std::unique_ptr<SceneRun> run = start_run(resolved, arguments.scene);
  check_trails(options.trails, *run, "--trails");
  check_view_bodies(arguments.view, *run);
  const auto [width, height] = write_contact_sheet(*run, plan, options, output);
  warn_divergences(*run);
  if (arguments.quiet) return;
  out << "wrote a " << width << "x" << height << " contact sheet of " << plan.frames.size()
      << " frames of " << resolved.scene.name << " to " << output.string() << "\n";
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
  command->add_option("--count,-c", sheet->count, "frames spread evenly over the run")
      ->capture_default_str();
  command->add_option("--steps", sheet->scene.steps,
                      "length of the run in steps (default: the scene's)");
  command->add_option("--columns", sheet->columns, "tiles per row")->capture_default_str();
  command->add_option("--tile", sheet->tile, "tile size WxH in pixels")->capture_default_str();
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
  result.dry_run = [sheet](std::ostream&) { check_scene_arguments(sheet->scene, sheet->frames); };
  result.run = [sheet, &options](std::ostream& out) {
    sheet->quiet = options.quiet;
    sheet_scene(*sheet, out);
    return 0;
  };
  return result;
}

}  // namespace impulse2d::demos

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
  std::optional<std::string> scenes;    ///< several scenes side by side: comma-separated names
  std::optional<std::string> trails;    ///< `dynamic` or body indices with motion trails
  ViewArguments view;                   ///< legend, scales, camera, highlight
};

/// One scene of a contact sheet, checked and ready.
struct SheetScene {
  std::string argument;            ///< as given: a built-in name or a .json file
  ResolvedScene resolved;          ///< the scene, its parameters and length
  FramePlan plan;                  ///< the steps shown
  DebugDrawOptions draw;           ///< its overlays
  std::unique_ptr<SceneRun> run;   ///< the run, built and not yet stepped
};

/// A contact sheet, checked and ready: what `sheet_scene` runs and `print_sheet_plan` shows.
struct SheetJob {
  std::vector<SheetScene> scenes;  ///< one, or several side by side (--scenes)
  ContactSheetOptions options;     ///< layout and looks
  std::filesystem::path output;    ///< the PNG
  std::pair<int, int> size;        ///< the sheet's width and height, pixels
};

/// The scene names of --scenes (comma-separated, none empty).
std::vector<std::string> scene_list(const std::string& text) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    names.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (names.back().empty()) {
      throw UsageError("--scenes " + text + ": a scene name is empty (write names separated by commas: pendulum,car)");
    }
    if (comma == std::string::npos) return names;
    start = comma + 1;
  }
}

/// Every check a contact sheet makes before any work; the run and --dry-run both start here.
/// Throws `UsageError` for bad input, `std::runtime_error` for an unwritable --out folder.
SheetJob prepare_sheet(const SheetArguments& arguments) {
  SheetJob job;
  std::vector<std::string> names;
  if (arguments.scenes) {
    if (!arguments.scene.scene.empty()) {
      throw UsageError("give one scene or --scenes, not both (" + arguments.scene.scene + " and --scenes " +
                       *arguments.scenes + ")");
    }
    names = scene_list(*arguments.scenes);
    if (names.size() > 1 && !arguments.scene.params.empty()) {
      throw UsageError("--param applies to one scene; --scenes names " + std::to_string(names.size()));
    }
    if (names.size() > 1 && arguments.trails) {
      throw UsageError("--trails names bodies of one scene; --scenes names " + std::to_string(names.size()));
    }
  } else {
    names.push_back(arguments.scene.scene.empty() ? default_scene().name : arguments.scene.scene);
  }
  if (arguments.count < 1 || arguments.count > 256) {
    throw UsageError("--count " + std::to_string(arguments.count) + ": must be 1..256");
  }
  ContactSheetOptions& options = job.options;
  std::tie(options.tile_width, options.tile_height) = parse_size(arguments.tile, "--tile");
  if (arguments.columns < 1) {
    throw UsageError("--columns " + std::to_string(arguments.columns) + ": must be at least 1");
  }
  options.columns = arguments.columns;
  std::optional<std::uint32_t> overlay_flags;
  if (arguments.overlays) overlay_flags = parse_overlays_option(*arguments.overlays);
  options.theme = theme_of(arguments.theme);
  if (arguments.trails) options.trails = parse_trails(*arguments.trails, "--trails");
  int tiles = 0;
  for (const std::string& name : names) {
    SheetScene scene;
    scene.argument = name;
    SceneArguments scene_arguments = arguments.scene;
    scene_arguments.scene = name;
    scene.resolved = resolve(scene_arguments);
    apply_view_arguments(arguments.view, scene.resolved.scene);
    scene.plan = arguments.frames ? plan_frames(*arguments.frames, scene.resolved.steps)
                                  : spread_frames(arguments.count, scene.resolved.steps);
    scene.draw = scene.resolved.scene.view.draw;
    if (overlay_flags) scene.draw.flags = *overlay_flags;
    tiles += static_cast<int>(scene.plan.frames.size());
    job.scenes.push_back(std::move(scene));
  }
  const SheetScene& first = job.scenes.front();
  if (job.scenes.size() == 1) {
    options.caption = (first.resolved.params.specs().empty() ? "no parameters" : first.resolved.params.summary()) +
                      "  |  overlays: " + overlay_list(first.draw.flags);
  } else {
    options.caption = "scenes: " + *arguments.scenes + "  |  overlays: " +
                      (overlay_flags ? overlay_list(*overlay_flags) : std::string("each scene's own"));
  }
  if (arguments.trails) options.caption += "  |  trails: " + *arguments.trails;
  job.size = contact_sheet_size(tiles, options);
  const std::string stem = job.scenes.size() == 1 ? first.resolved.scene.name : "scenes";
  job.output = arguments.out ? std::filesystem::path(*arguments.out)
                             : std::filesystem::path("out") / ("contact_sheet_" + stem + ".png");
  if (job.output.extension() != ".png") {
    throw UsageError("--out " + job.output.string() + ": must end in .png");
  }

  for (SheetScene& scene : job.scenes) {
    SceneArguments scene_arguments = arguments.scene;
    scene_arguments.scene = scene.argument;
    scene.run = start_run(scene.resolved, scene_arguments);
    check_trails(options.trails, *scene.run, "--trails");
    check_view_bodies(arguments.view, *scene.run);
    check_camera(arguments.view, *scene.run, options.tile_width, options.tile_height);
  }
  check_output_folder(job.output.parent_path(), "--out " + job.output.string());
  return job;
}

/// What `sheet` would do, for --dry-run.
void print_sheet_plan(const SheetJob& job, std::ostream& out) {
  std::size_t tiles = 0;
  for (const SheetScene& scene : job.scenes) {
    tiles += scene.plan.frames.size();
    out << "dry run: sheet " << scene.resolved.scene.name << " (" << scene.resolved.scene.source << ")\n"
        << "  parameters: "
        << (scene.resolved.params.specs().empty() ? "none" : scene.resolved.params.summary()) << "\n"
        << "  steps: " << scene.plan.steps << " of " << scene.resolved.steps << "\n"
        << "  frames: " << scene.plan.frames.size() << ": " << describe_frame_steps(scene.plan) << "\n"
        << "  overlays: " << overlay_list(scene.draw.flags) << "\n";
  }
  out << "  tiles: " << tiles << " of " << job.options.tile_width << "x" << job.options.tile_height << " in "
      << std::min<std::size_t>(static_cast<std::size_t>(job.options.columns), tiles)
      << " columns, theme " << render::theme_name(job.options.theme) << "\n"
      << "  writes: " << job.output.string() << " (" << job.size.first << "x" << job.size.second
      << " pixels)\n"
      << "nothing was run or written\n";
}

/// Writes the contact sheet of `job`; prints where it went unless `quiet`.
void sheet_scene(SheetJob& job, bool quiet, std::ostream& out) {
  std::vector<SheetSource> sources;
  std::size_t tiles = 0;
  for (SheetScene& scene : job.scenes) {
    sources.push_back(SheetSource{scene.run.get(), scene.plan, scene.draw});
    tiles += scene.plan.frames.size();
  }
  const auto [width, height] = write_contact_sheet(sources, job.options, job.output);
  for (SheetScene& scene : job.scenes) warn_divergences(*scene.run);
  if (quiet) return;
  const std::string what = job.scenes.size() == 1 ? job.scenes.front().resolved.scene.name
                                                  : std::to_string(job.scenes.size()) + " scenes";
  out << "wrote a " << width << "x" << height << " contact sheet of " << tiles << " frames of " << what
      << " to " << job.output.string() << "\n";
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
  command->add_option("--out,-o", sheet->out,
                      "PNG file (default: out/contact_sheet_<scene>.png, with --scenes "
                      "out/contact_sheet_scenes.png)");
  command->add_option("--scenes", sheet->scenes,
                      "several scenes side by side instead of one: comma-separated names or "
                      ".json files, each with --frames/--count tiles (its own overlays unless "
                      "--overlays); not with --param or --trails");
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

/// @file commands.cpp
#include "app/commands.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "frames/contact_sheet.h"
#include "frames/frame_sequence.h"
#include "scene/overlays.h"
#include "frames/progress.h"
#include "scene/run_limits.h"
#include "demos/scene_registry.h"
#include "scene/scene_run.h"
#include "scene/trace_writer.h"
#include "scene/usage_error.h"
#include "frames/video_encoder.h"

namespace impulse2d::demos {
namespace {

/// A scene resolved from the arguments together with its parameters.
struct ResolvedScene {
  Scene scene;
  Params params;
  std::int64_t steps = 0;
};

ResolvedScene resolve(const SceneArguments& arguments) {
  ResolvedScene resolved{resolve_scene(arguments.scene), Params{}, 0};
  resolved.params = Params(resolved.scene.params);
  for (const std::string& assignment : arguments.params) resolved.params.set_assignment(assignment);
  resolved.steps = arguments.steps ? *arguments.steps : resolved.scene.view.steps;
  if (resolved.steps < 0 || resolved.steps > limits::max_steps) {
    throw UsageError("--steps " + std::to_string(resolved.steps) + ": must be 0.." +
                     std::to_string(limits::max_steps));
  }
  for (const SceneEvent& event : resolved.scene.events) {
    if (event.step > resolved.steps) {
      throw UsageError(resolved.scene.source + ": " + event.origin + ".step: step " +
                       std::to_string(event.step) + " is after the end of the run (steps 0.." +
                       std::to_string(resolved.steps) +
                       "; change it with --steps or the file's run.steps)");
    }
  }
  return resolved;
}

/// A run of the resolved scene, strict when asked.
std::unique_ptr<SceneRun> start_run(const ResolvedScene& resolved, const SceneArguments& arguments) {
  auto run = std::make_unique<SceneRun>(resolved.scene, resolved.params);
  run->set_strict(arguments.strict);
  return run;
}

/// Throws `UsageError` for a trail body index no body of the run can have.
void check_trails(const TrailSelection& trails, const SceneRun& run, const std::string& option) {
  for (const std::uint32_t slot : trails.slots) {
    if (slot >= static_cast<std::uint32_t>(run.bodies_in_run())) {
      throw UsageError(option + ": body " + std::to_string(slot) + " does not exist (scene " +
                       run.scene().name + " has " + std::to_string(run.bodies_in_run()) +
                       " bodies, 0.." + std::to_string(run.bodies_in_run() - 1) + ")");
    }
  }
}

/// Prints a warning per diverged body (the first 10, then a count) to stderr.
void warn_divergences(const SceneRun& run) {
  const std::vector<Divergence>& divergences = run.divergences();
  for (std::size_t i = 0; i < divergences.size() && i < 10; ++i) {
    std::cerr << "impulse2d: warning: " << describe_divergence(run.scene(), divergences[i])
              << "\n";
  }
  if (divergences.size() > 10) {
    std::cerr << "impulse2d: warning: ... and " << divergences.size() - 10
              << " more divergences (--strict stops at the first)\n";
  }
}

render::Theme theme_of(const std::string& name) {
  const std::optional<render::Theme> theme = render::parse_theme(name);
  if (!theme) throw UsageError("--theme '" + name + "': expected light or dark");
  return *theme;
}

}  // namespace

std::pair<int, int> parse_size(const std::string& text, const std::string& option) {
  const std::size_t x = text.find('x');
  const auto parse = [&](const std::string& part) {
    char* end = nullptr;
    const long value = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end != '\0' || value < 16 || value > 8192) {
      throw UsageError(option + " '" + text +
                       "': expected WxH with each side 16..8192 pixels, e.g. 800x600");
    }
    return static_cast<int>(value);
  };
  if (x == std::string::npos) parse("");
  return {parse(text.substr(0, x)), parse(text.substr(x + 1))};
}

void check_scene_arguments(const SceneArguments& arguments,
                           const std::optional<std::string>& frames) {
  SceneArguments checked = arguments;
  if (checked.scene.empty()) checked.scene = default_scene().name;
  const ResolvedScene resolved = resolve(checked);
  if (frames) plan_frames(*frames, resolved.steps);
}

void list_scenes(std::ostream& out) {
  for (const Scene& scene : builtin_scenes()) {
    out << scene.name << "\n  " << scene.description << "\n  model: " << describe_model(scene.model)
        << "\n  run: " << scene.view.steps << " steps, frames " << scene.view.frames << "\n";
    for (const ParamSpec& param : scene.params) {
      out << "  --param " << param.name << "=" << format_param_value(param.default_value) << "  ("
          << format_param_value(param.minimum) << ".." << format_param_value(param.maximum) << ") "
          << param.description << "\n";
    }
  }
  out << "\nA scene file (.json) can be given wherever a scene name is accepted.\n";
}

void render_scene(const RenderArguments& arguments, std::ostream& out) {
  ResolvedScene resolved = resolve(arguments.scene);
  apply_view_arguments(arguments.view, resolved.scene);
  const FramePlan plan = plan_frames(
      arguments.frames ? *arguments.frames : resolved.scene.view.frames, resolved.steps);
  FrameSequenceOptions options;
  std::tie(options.width, options.height) = parse_size(arguments.size, "--size");
  if (static_cast<std::int64_t>(options.width) * options.height > limits::max_frame_pixels) {
    throw UsageError("--size " + arguments.size + ": " +
                     std::to_string(static_cast<std::int64_t>(options.width) * options.height) +
                     " pixels per frame; the limit is " + std::to_string(limits::max_frame_pixels) +
                     " (4096x4096)");
  }
  options.clean = arguments.clean;
  options.draw = resolved.scene.view.draw;
  if (arguments.overlays) options.draw.flags = parse_overlays(*arguments.overlays);
  options.theme = theme_of(arguments.theme);
  options.directory = arguments.out;
  if (arguments.threads < 1 || arguments.threads > 64) throw UsageError("--threads must be 1..64");
  options.writer_threads = arguments.threads;
  if (arguments.trails) options.trails = parse_trails(*arguments.trails, "--trails");
  options.write_frames = !arguments.no_frames;
  if (arguments.html && arguments.no_frames) {
    throw UsageError("--html shows the PNG frames: it cannot be combined with --no-frames");
  }
  options.html = arguments.html;
  if (arguments.no_frames && !arguments.video) {
    throw UsageError("--no-frames needs --video FILE (otherwise nothing would be written)");
  }
  if (arguments.fps) {
    if (!arguments.video) throw UsageError("--fps sets the video's rate: it needs --video FILE");
    if (!(*arguments.fps >= 1.0 && *arguments.fps <= 240.0)) {
      throw UsageError("--fps " + format_param_value(*arguments.fps) + ": must be 1..240");
    }
    options.frames_per_second = *arguments.fps;
  }
  if (arguments.video) {
    check_video_output(*arguments.video);
    options.video = std::filesystem::path(*arguments.video);
  }
  for (const ParamSpec& spec : resolved.params.specs()) {
    const double value = resolved.params.number(spec.name);
    if (value == spec.default_value) continue;
    options.parameters += (options.parameters.empty() ? "" : " ") + spec.name + "=" +
                          format_param_value(value);
  }

  const std::unique_ptr<SceneRun> run = start_run(resolved, arguments.scene);
  check_trails(options.trails, *run, "--trails");
  check_view_bodies(arguments.view, *run);
  std::unique_ptr<Progress> progress;
  if (!arguments.quiet) {
    progress = std::make_unique<Progress>(
        resolved.scene.name, static_cast<std::int64_t>(plan.frames.size()), stderr,
        is_terminal(stderr));
  }
  const FrameSequenceResult result = render_frame_sequence(
      *run, plan, options, [&](std::int64_t done) {
        if (progress) progress->update(done);
      });
  if (progress) progress->finish();
  warn_divergences(*run);
  if (arguments.quiet) return;
  out << "wrote " << result.frame_count << " frames of " << resolved.scene.name;
  if (options.write_frames) {
    out << " to " << options.directory.string() << "/ (" << result.first_file.string() << " .. "
        << result.last_file.string() << ", index " << result.index_file.string();
    if (options.html) out << ", viewer " << result.html_file.string();
    out << ")";
    if (options.video) out << " and";
  }
  if (options.video) out << " to " << options.video->string();
  out << "\n";
}

void trace_scene(const TraceArguments& arguments, std::ostream& out) {
  const ResolvedScene resolved = resolve(arguments.scene);
  TraceFormat format = TraceFormat::Csv;
  if (arguments.format == "json") {
    format = TraceFormat::Json;
  } else if (arguments.format != "csv") {
    throw UsageError("--format '" + arguments.format + "': expected csv or json");
  }
  const std::unique_ptr<SceneRun> run = start_run(resolved, arguments.scene);
  if (arguments.every < 1) throw UsageError("--every must be >= 1");
  std::int64_t moving = 0;
  for (const BodyId id : run->world().body_ids()) {
    moving += run->world().body(id).type == BodyType::Static ? 0 : 1;
  }
  const std::int64_t samples = resolved.steps / arguments.every + 2;
  if (moving > 0 && samples > limits::max_trace_rows / moving) {
    throw UsageError("trace: --steps " + std::to_string(resolved.steps) + " --every " +
                     std::to_string(arguments.every) + " would print about " +
                     std::to_string(samples) + " samples of " + std::to_string(moving) +
                     " bodies; the limit is " + std::to_string(limits::max_trace_rows) +
                     " rows (raise --every or lower --steps)");
  }
  const std::string text = trace_run(*run, resolved.steps, arguments.every, format);
  warn_divergences(*run);
  out << text;
}

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

}  // namespace impulse2d::demos

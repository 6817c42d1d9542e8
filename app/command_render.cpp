/// @file command_render.cpp
/// `impulse2d render`: a scene into a PNG frame sequence (and a video, a browser viewer);
/// with no command at all, the default demo into out/.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <system_error>

#include "app/command.h"
#include "app/scene_command.h"
#include "app/state_file.h"
#include "app/strict_number_check.h"
#include "app/view_options.h"
#include "demos/scene_registry.h"
#include "frames/frame_index.h"
#include "frames/frame_plan.h"
#include "frames/frame_sequence.h"
#include "frames/html_viewer.h"
#include "frames/overlay_variants.h"
#include "frames/output_guard.h"
#include "frames/progress.h"
#include "frames/video_encoder.h"
#include "render/frame_writer.h"
#include "frames/contact_sheet.h"
#include "scene/run_limits.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d render`.
struct RenderArguments {
  SceneArguments scene;                 ///< what to run
  std::optional<std::string> frames;    ///< `A:B:k` ranges; the scene's default when absent
  std::string size = "800x600";         ///< WxH pixels
  std::optional<std::string> overlays;  ///< overlay list; the scene's default when absent
  std::string theme = "light";          ///< light or dark
  std::string out = "out";              ///< directory
  std::optional<std::string> video;     ///< .mp4 / .webm / .gif path
  std::optional<double> fps;            ///< video frames per second; real time when absent
  bool no_frames = false;               ///< write the video only, no PNG frames
  int threads = 2;                      ///< PNG encoding threads
  std::optional<std::string> trails;    ///< `dynamic` or body indices with motion trails
  bool clean = false;                   ///< replace frames of the same scene already in `out`
  bool quiet = false;                   ///< no progress and no summary line
  ViewArguments view;                   ///< HUD, legend, scales, camera, highlight
  bool html = false;                    ///< also write the browser viewer `<scene>.html`
  std::string load_state;               ///< start from a world saved by trace --save-state
};

/// Creates the folder the video goes into when it is missing (with --no-frames nothing else
/// does), before any rendering; `guard` removes it again when the run fails. Throws when it
/// cannot be created.
void prepare_video_folder(const std::filesystem::path& video, OutputGuard& guard) {
  const std::filesystem::path folder = video.parent_path();
  if (folder.empty()) return;
  std::error_code error;
  if (std::filesystem::is_directory(folder, error)) return;
  guard.will_create_directory(folder);
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw std::runtime_error("--video " + video.string() + ": cannot create the folder " +
                             folder.string() + ": " + error.message());
  }
}

/// A render, checked and ready: what `render_scene` runs and `print_render_plan` describes.
struct RenderJob {
  ResolvedScene resolved;         ///< the scene, its parameters and length
  FramePlan plan;                 ///< the steps drawn
  FrameSequenceOptions options;   ///< looks and outputs
  std::unique_ptr<SceneRun> run;  ///< the run, built and not yet stepped
  std::vector<std::filesystem::path> replaced;  ///< earlier frames --clean replaces
};

/// Every check a render makes before any work, in the order the run made them; the run and
/// --dry-run both start here, so they cannot disagree. Throws `UsageError` for bad input and
/// `std::runtime_error` for an output that cannot be written or a missing ffmpeg.
RenderJob prepare_render(const RenderArguments& arguments) {
  RenderJob job;
  job.resolved = resolve(arguments.scene);
  ResolvedScene& resolved = job.resolved;
  apply_view_arguments(arguments.view, resolved.scene);
  job.plan = plan_frames(arguments.frames ? *arguments.frames : resolved.scene.view.frames,
                         resolved.steps);
  FrameSequenceOptions& options = job.options;
  std::tie(options.width, options.height) = parse_size(arguments.size, "--size");
  if (static_cast<std::int64_t>(options.width) * options.height > limits::max_frame_pixels) {
    throw UsageError("--size " + arguments.size + ": " +
                     std::to_string(static_cast<std::int64_t>(options.width) * options.height) +
                     " pixels per frame; the limit is " + std::to_string(limits::max_frame_pixels) +
                     " (4096x4096)");
  }
  options.clean = arguments.clean;
  options.draw = resolved.scene.view.draw;
  if (arguments.overlays) options.draw.flags = parse_overlays_option(*arguments.overlays);
  options.theme = theme_of(arguments.theme);
  options.directory = arguments.out;
  if (arguments.threads < 1 || arguments.threads > 64) {
    throw UsageError("--threads " + std::to_string(arguments.threads) + ": must be 1..64");
  }
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

  job.run = start_run(resolved, arguments.scene);
  if (!arguments.load_state.empty()) load_state_file(arguments.load_state, *job.run);
  check_trails(options.trails, *job.run, "--trails");
  check_view_bodies(arguments.view, *job.run);
  check_camera(arguments.view, *job.run, options.width, options.height);
  job.replaced = check_sequence_output(resolved.scene.name, options);
  return job;
}

/// The PNG bytes of `count` frames, as a range in megabytes: these frames of flat colours
/// compress to 0.04-0.9 bytes a pixel (800x600 measured: pyramid 20 KB, ball_pit with every
/// overlay 410 KB). "3..60 MB".
std::string approximate_size(std::int64_t count, const FrameSequenceOptions& options) {
  const double pixels = static_cast<double>(count) * options.width * options.height;
  const auto megabytes = [](double bytes) {
    return bytes < 1e6 ? std::string("<1") : std::to_string(static_cast<std::int64_t>(bytes / 1e6 + 0.5));
  };
  return megabytes(0.04 * pixels) + ".." + megabytes(0.9 * pixels) + " MB";
}

/// What a render of `job` would do, for --dry-run: the scene, the steps drawn, the frame
/// size and the files it would write.
void print_render_plan(const RenderJob& job, std::ostream& out) {
  const FrameSequenceOptions& options = job.options;
  const std::string& name = job.resolved.scene.name;
  const std::int64_t count = static_cast<std::int64_t>(job.plan.frames.size());
  out << "dry run: render " << name << " (" << job.resolved.scene.source << ")\n"
      << "  parameters: "
      << (job.resolved.params.specs().empty() ? "none" : job.resolved.params.summary()) << "\n"
      << "  steps: " << job.plan.steps << " of " << job.resolved.steps << "\n"
      << "  frames: " << count << ": " << describe_frame_steps(job.plan) << "\n"
      << "  frame size: " << options.width << "x" << options.height
      << ", overlays: " << overlay_list(options.draw.flags) << ", theme " << render::theme_name(options.theme) << "\n";
  if (options.write_frames) {
    const int digits = frame_number_digits(count);
    out << "  writes: " << render::frame_file_path(options.directory, name, 0, digits).string()
        << " .. " << render::frame_file_path(options.directory, name, count - 1, digits).string()
        << ", " << frame_index_path(options.directory, name).string();
    if (options.html) {
      out << ", " << html_viewer_path(options.directory, name).string() << ", "
          << overlay_variants_path(options.directory, name).string() << "/";
    }
    out << "\n  size: " << approximate_size(count, options)
        << " of PNG (0.04-0.9 bytes a pixel, by how busy the frames are)\n";
    if (!job.replaced.empty()) {
      out << "  replaces: " << job.replaced.size() << " files of an earlier run (--clean)\n";
    }
  }
  if (options.video) {
    out << "  video: " << options.video->string() << " ("
        << (options.frames_per_second ? format_param_value(*options.frames_per_second) + " fps"
                                      : std::string("real time"))
        << ")\n";
  }
  out << "nothing was run or written\n";
}

/// Renders a frame sequence (and optionally a video); prints where the frames went unless
/// `quiet`.
void render_scene(RenderJob& job, bool quiet, std::ostream& out) {
  const FrameSequenceOptions& options = job.options;
  OutputGuard video_folder;
  if (options.video) prepare_video_folder(*options.video, video_folder);
  std::unique_ptr<Progress> progress;
  if (!quiet) {
    progress = std::make_unique<Progress>(job.resolved.scene.name,
                                          static_cast<std::int64_t>(job.plan.frames.size()),
                                          stderr, is_terminal(stderr));
  }
  const FrameSequenceResult result = render_frame_sequence(
      *job.run, job.plan, options, [&](std::int64_t done) {
        if (progress) progress->update(done);
      });
  if (progress) progress->finish();
  video_folder.commit();
  warn_divergences(*job.run);
  if (quiet) return;
  out << "wrote " << result.frame_count << " frames of " << job.resolved.scene.name;
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

/// The run or, with --dry-run, the plan of `arguments`.
void render_or_plan(const RenderArguments& arguments, bool dry_run, std::ostream& out) {
  RenderJob job = prepare_render(arguments);
  if (dry_run) {
    print_render_plan(job, out);
  } else {
    render_scene(job, arguments.quiet, out);
  }
}

}  // namespace

Command add_render_command(CLI::App& program, ProgramOptions& options) {
  auto render = std::make_shared<RenderArguments>();
  CLI::App* command = program.add_subcommand("render", "render a scene into a PNG frame sequence");
  add_scene_options(*command, render->scene, true);
  add_backend_option(*command, options.backend);
  command->add_option(
      "--frames,-f", render->frames,
      "steps to draw: A:B[:k] ranges, comma-separated (step n = the world after n steps)");
  command->add_option("--steps", render->scene.steps,
                      "length of the run in steps (default: the scene's)")
      ->check(whole_number_check());
  command->add_option("--size,-s", render->size, "frame size WxH in pixels, each side 16..8192")
      ->capture_default_str();
  command->add_option("--overlays", render->overlays, overlay_help());
  command->add_option("--theme", render->theme, "light or dark")->capture_default_str();
  command->add_option("--out,-o", render->out,
                      "output directory: <scene>_00000.png, <scene>_00001.png, ... (one "
                      "per frame, numbered from 0 whatever steps they show) and "
                      "<scene>_frames.csv (frame,step,time,file)")
      ->capture_default_str()
      ->check(
          [](const std::string& out) -> std::string {
            const std::string extension = std::filesystem::path(out).extension().string();
            if (extension != ".mp4" && extension != ".webm" && extension != ".gif") return "";
            return "-o names the folder of the PNG frames, not a video: write --video " + out +
                   " (with --no-frames for the video alone)";
          },
          "");
  command->add_option("--video", render->video,
                      "also write a video (.mp4, .webm or .gif; needs ffmpeg)");
  command->add_option("--fps", render->fps,
                      "video frames per second, 1..240 (default: real time)")
      ->check(decimal_check());
  command->add_flag("--no-frames", render->no_frames, "write the --video only, no PNG frames");
  command->add_option("--threads", render->threads, "PNG encoding threads, 1..64")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_option("--trails", render->trails,
                      "motion trails: 'dynamic' (every dynamic body) or body indices "
                      "3,7,12 (as the ids overlay shows them)");
  command->add_flag("--html", render->html,
                    "also write <scene>.html beside the frames: a viewer for the browser "
                    "(scrubber, play/pause, step/time/energy/contacts, timeline) with an "
                    "overlay switch pre-rendered into <scene>.overlays/");
  command->add_option("--load-state", render->load_state,
                      "start from a world saved by `trace --save-state` of the same scene (frame "
                      "steps stay the run's own: frames before the saved step show it as saved)");
  command->add_flag("--clean", render->clean,
                    "replace frames of the same scene already in the output directory "
                    "(without it they are an error); done only when the run succeeds");
  add_view_options(*command, render->view, true);

  Command result;
  result.parser = command;
  result.renders = true;
  result.dry_run = [render](std::ostream& out) { render_or_plan(*render, true, out); };
  result.run = [render, &options](std::ostream& out) {
    render->quiet = options.quiet;
    render_or_plan(*render, false, out);
    return 0;
  };
  return result;
}

void render_default_demo(const ProgramOptions& options, std::ostream& out) {
  RenderArguments demo;
  demo.quiet = options.quiet;
  demo.scene.scene = default_scene().name;
  // What the README's first paragraph promises: the contacts' normals, impulses and overlaps.
  demo.overlays = default_demo_overlays;
  demo.clean = true;  // the default demo always refreshes out/<default scene>_*.png
  render_or_plan(demo, options.dry_run, out);
}

}  // namespace impulse2d::demos

/// @file frame_sequence.cpp
#include "frames/frame_sequence.h"

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "frames/contact_sheet.h"
#include "frames/frame_index.h"
#include "frames/frame_metadata.h"
#include "frames/html_viewer.h"
#include "scene/interrupt.h"
#include "frames/output_guard.h"
#include "frames/output_folder.h"
#include "frames/output_staging.h"
#include "frames/overlay_variants.h"
#include "scene/usage_error.h"
#include "frames/scene_camera.h"
#include "frames/timeline_frames.h"
#include "scene/trace_writer.h"
#include "frames/video_encoder.h"
#include "frames/view_frame_options.h"
#include "render/event_marks.h"
#include "render/frame_renderer.h"
#include "render/frame_writer.h"
#include "render/motion_trails.h"
#include "image/png_text.h"
#include "golden/sidecar.h"

namespace impulse2d::demos {
namespace {

/// Playback rate that shows the run in real time: one frame per `stride` steps of `dt`
/// seconds, where the stride is the distance between the first two frames.
double real_time_rate(const FramePlan& plan, float dt) {
  const std::int64_t stride = plan.frames.size() > 1 ? plan.frames[1] - plan.frames[0] : 1;
  const double rate = 1.0 / (static_cast<double>(stride) * static_cast<double>(dt));
  return std::min(120.0, std::max(1.0, std::round(rate)));
}

}  // namespace

std::string scene_title(const Scene& scene) {
  return scene.view.caption.empty() ? scene.name : scene.name + " - " + scene.view.caption;
}

namespace {

/// PNG metadata of frames rendered but not yet written, by frame number: filled by the
/// rendering thread, taken by the writer's worker threads.
class PendingMetadata {
 public:
  /// Keeps `text` for frame `frame_number`.
  void put(std::int64_t frame_number, image::PngText text) {
    std::lock_guard<std::mutex> lock(mutex_);
    texts_[frame_number] = std::move(text);
  }
  /// `png` with frame `frame_number`'s metadata inserted (and forgotten).
  std::vector<std::uint8_t> annotate(std::int64_t frame_number, std::vector<std::uint8_t> png) {
    image::PngText text;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      const auto found = texts_.find(frame_number);
      if (found == texts_.end()) return png;
      text = std::move(found->second);
      texts_.erase(found);
    }
    return image::with_png_text(png, text);
  }

 private:
  std::mutex mutex_;
  std::map<std::int64_t, image::PngText> texts_;
};

/// The rendering itself: frames into `staging` (when given), the video, then publishes.
FrameSequenceResult render_staged(SceneRun& run, const FramePlan& plan,
                                  const FrameSequenceOptions& options,
                                  const FrameProgress& progress, OutputGuard& guard,
                                  const std::vector<std::filesystem::path>& old_frames,
                                  std::int64_t& frames_done) {
  const std::string& scene_name = run.scene().name;
  // Declared in this order so that the writer's workers stop before the metadata they read
  // and the staging directory they write into go.
  std::unique_ptr<StagingDirectory> staging;
  PendingMetadata metadata;
  std::unique_ptr<render::AsyncFrameWriter> writer;
  const int digits = frame_number_digits(static_cast<std::int64_t>(plan.frames.size()));
  if (options.write_frames) {
    staging = std::make_unique<StagingDirectory>(options.directory, scene_name);
    render::FrameWriterOptions writer_options;
    writer_options.directory = staging->path();
    writer_options.scene_name = scene_name;
    writer_options.worker_threads = options.writer_threads;
    writer_options.digits = digits;
    writer_options.annotate = [&metadata](std::int64_t frame_number, std::vector<std::uint8_t> png) {
      return metadata.annotate(frame_number, std::move(png));
    };
    writer = std::make_unique<render::AsyncFrameWriter>(writer_options);
  }
  // The viewer's overlay switch: each frame rendered again per variant, one writer each.
  const bool html = options.html && options.write_frames;  // the page shows the PNG frames
  const std::vector<OverlayVariant> variants =
      html ? overlay_variants(options.draw.flags) : std::vector<OverlayVariant>{};
  std::vector<std::unique_ptr<render::AsyncFrameWriter>> variant_writers;
  for (const OverlayVariant& variant : variants) {
    render::FrameWriterOptions variant_options;
    variant_options.directory = overlay_variants_path(staging->path(), scene_name) / variant.name;
    variant_options.scene_name = scene_name;
    variant_options.digits = digits;
    variant_writers.push_back(std::make_unique<render::AsyncFrameWriter>(variant_options));
  }

  std::unique_ptr<TimelineFrames> timeline;
  if (run.scene().view.show_timeline && !plan.frames.empty()) {
    timeline = std::make_unique<TimelineFrames>(run, plan.frames.back(), options.width, options.height,
                                                options.theme);
  }
  std::unique_ptr<VideoEncoder> video;
  if (options.video) {
    guard.will_write_file(*options.video);
    const double rate = options.frames_per_second
                            ? *options.frames_per_second
                            : real_time_rate(plan, run.world().settings().time_step);
    video = std::make_unique<VideoEncoder>(
        *options.video, options.width,
        options.height + (timeline ? timeline->strip_height() : 0), rate);
  }

  render::FrameRenderer renderer(options.width, options.height);
  const std::string fingerprint = golden::split_fingerprint(renderer.fingerprint()).describe();
  const std::string scene_label =
      run.scene().source == "built-in" ? scene_name : scene_name + " (" + run.scene().source + ")";
  const render::Camera camera = run_camera(run, options.width, options.height);
  render::FrameOptions frame_options = view_frame_options(run, options.draw, options.theme);
  render::HudInfo hud;
  hud.scene_name = scene_title(run.scene());
  constexpr std::size_t trail_points = 240;  // 4 s of path at 60 steps per second
  render::MotionTrails trails(trail_points);
  if (!options.trails.empty()) {
    frame_options.trails = &trails;
    record_trails(options.trails, run.world(), trails);
  }
  // A frame shows the events of the steps since the frame before it.
  render::EventMarks events;
  const bool record_events = (options.draw.flags & draw_events) != 0;
  if (record_events) {
    frame_options.events = &events;
    events.start(run.world());
  }

  FrameSequenceResult result;
  std::vector<FrameIndexRow> index;
  ViewerPage viewer;
  for (const std::int64_t frame_step : plan.frames) {
    while (run.step_count() < frame_step) {
      run.step();
      if (!options.trails.empty()) record_trails(options.trails, run.world(), trails);
      if (record_events) events.record(run.world(), run.step_count());
    }
    check_interrupt();
    hud.step = frame_step;
    hud.frame_index = result.frame_count;  // the file's number
    update_view_frame(run, frame_options, hud);
    render::Frame frame = writer ? writer->take_spare_frame() : render::Frame{};
    renderer.render(run.world(), frame_camera(camera, run), frame_options, hud, frame);
    if (timeline) timeline->append(frame, frame_step);
    if (video) video->add(frame);
    const std::int64_t number = result.frame_count;
    if (writer) {
      const std::filesystem::path file =
          render::frame_file_path(options.directory, scene_name, number, digits);
      if (number == 0) result.first_file = file;
      result.last_file = file;
      index.push_back(FrameIndexRow{number, frame_step, run.world().time(),
                                    file.filename().string()});
      if (html) {
        viewer.frames.push_back(ViewerFrame{index.back(), mechanical_energy(run.world()),
                                            contact_count(run.world()),
                                            render::count_event_marks(events.marks())});
      }
      metadata.put(number, frame_metadata(scene_label, options.parameters, run.world(), fingerprint));
      writer->submit(number, std::move(frame));
    }
    for (std::size_t i = 0; i < variants.size(); ++i) {
      render::FrameOptions variant_options = frame_options;
      variant_options.draw.flags = variants[i].flags;
      render::Frame variant_frame = variant_writers[i]->take_spare_frame();
      renderer.render(run.world(), frame_camera(camera, run), variant_options, hud, variant_frame);
      variant_writers[i]->submit(number, std::move(variant_frame));
    }
    events.clear();
    ++result.frame_count;
    frames_done = result.frame_count;
    if (progress) progress(result.frame_count);
  }
  if (writer) {
    writer->finish();
    write_frame_index(frame_index_path(staging->path(), scene_name), index);
    result.index_file = frame_index_path(options.directory, scene_name);
  }
  if (html) {
    viewer.title = scene_title(run.scene());
    viewer.details = scene_label + "  |  " +
                     (options.parameters.empty() ? "default parameters" : options.parameters) +
                     "  |  overlays: " + overlay_list(options.draw.flags) + "  |  " +
                     std::to_string(options.width) + "x" + std::to_string(options.height);
    viewer.width = options.width;
    viewer.height = options.height;
    viewer.events = record_events;
    for (const std::unique_ptr<render::AsyncFrameWriter>& variant_writer : variant_writers) {
      variant_writer->finish();
    }
    if (!variants.empty()) viewer.variants.push_back({overlay_list(options.draw.flags), ""});
    for (const OverlayVariant& variant : variants) {
      const std::filesystem::path relative =
          overlay_variants_path(options.directory, scene_name).filename() / variant.name;
      viewer.variants.push_back({variant.name, relative.generic_string()});
    }
    write_html_viewer(html_viewer_path(staging->path(), scene_name), viewer);
    result.html_file = html_viewer_path(options.directory, scene_name);
  }
  if (video) video->finish();
  check_interrupt();
  // Success: from here on signals wait until the frames are in place.
  std::error_code ignored;
  for (const std::filesystem::path& old : old_frames) std::filesystem::remove_all(old, ignored);
  if (staging) staging->publish(guard);
  return result;
}

}  // namespace

std::vector<std::filesystem::path> check_sequence_output(const std::string& scene_name,
                                                         const FrameSequenceOptions& options) {
  if (options.video) check_output_folder(options.video->parent_path(), "--video " + options.video->string());
  if (!options.write_frames) return {};
  std::vector<std::filesystem::path> old_frames = existing_frames(options.directory, scene_name);
  const std::size_t frame_count = old_frames.size();
  // An earlier run's viewer and overlay variants go with its frames.
  for (const std::filesystem::path& viewer_file :
       {html_viewer_path(options.directory, scene_name),
        overlay_variants_path(options.directory, scene_name)}) {
    std::error_code missing;
    if (std::filesystem::exists(viewer_file, missing)) old_frames.push_back(viewer_file);
  }
  if (!old_frames.empty() && !options.clean) {
    throw UsageError(options.directory.string() + "/ already holds " +
                     (frame_count > 0 ? std::to_string(frame_count) + " frames of " + scene_name +
                                            " from an earlier run (" +
                                            old_frames.front().string() + " ..)"
                                      : old_frames.front().string() + " from an earlier run") +
                     "; pass --clean to replace them, or choose another --out");
  }
  check_output_folder(options.directory, "--out " + options.directory.string());
  return old_frames;
}

FrameSequenceResult render_frame_sequence(SceneRun& run, const FramePlan& plan,
                                          const FrameSequenceOptions& options,
                                          const FrameProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  OutputGuard guard;
  std::vector<std::filesystem::path> old_frames = check_sequence_output(run.scene().name, options);
  if (options.write_frames) {
    guard.will_create_directory(options.directory);
    std::error_code error;
    std::filesystem::create_directories(options.directory, error);
    if (error) {
      throw std::runtime_error("cannot create the output directory " +
                               options.directory.string() + ": " + error.message());
    }
  }
  std::int64_t frames_done = 0;
  FrameSequenceResult result;
  try {
    result = render_staged(run, plan, options, progress, guard, old_frames, frames_done);
  } catch (...) {
    const int signal_number = pending_signal();
    if (signal_number == 0) throw;
    std::string removed = "removed the " + std::to_string(frames_done) + " frames rendered so far";
    if (options.video) removed += " and the unfinished video";
    if (!guard.new_directories().empty()) {
      removed += " and the directory " + guard.new_directories().front().string() +
                 " this run created";
    }
    throw Interrupted(signal_number, "interrupted by " + signal_name(signal_number) + " after " +
                                         std::to_string(frames_done) + " of " +
                                         std::to_string(plan.frames.size()) + " frames: " +
                                         removed + "; nothing that existed before was changed");
  }
  guard.commit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace impulse2d::demos

// bench_render: how fast frames come out of the renderer, for 1000 bodies at 800x600 with
// the HUD and legend, once with every overlay on and once with shapes only.
//
//   bench_render [--frames N] [--warmup STEPS] [--out DIR] [--dump-frame FILE] [--render-only [--flags MASK]]
//   bench_render --ratio [--repeats N]
//   bench_render --state-ratio [--step N] [--frames N] [--only all|none]
//
// Prints a Markdown table: render ms/frame, wall-clock and CPU time of all threads (llvmpipe
// rasterises on its own threads); PNG encode ms/frame and size with image/'s `Small` setting
// (libdeflate level 12, the goldens'; the baseline) and its `Fast` one (libdeflate level 1,
// frame sequences'); and end-to-end frames/s of simulate+render+encode+write, first all on
// one thread with `Small` (the baseline), then with `Fast`, on this thread and on writer threads,
// with the CPU time of all threads per frame for the last. On a machine shared with other
// jobs the CPU times move much less than the wall-clock ones. Ratios are against the
// baselines measured in the same run. Frames go to DIR (default: a temporary directory
// that is removed afterwards); --dump-frame saves the last all-overlay frame (a PNG when FILE
// ends in .png, else raw RGBA).
// --render-only renders N every-overlay frames (a step between them) and nothing else, for
// profilers: e.g. `LP_NUM_THREADS=0 valgrind --tool=callgrind
// --toggle-collect='impulse2d::render::FrameRenderer::render(*' bench_render --render-only
// --frames 3` counts three renders (the first compiles the shaders: subtract a 1-frame run);
// --flags picks the overlays instead (core's DebugDrawFlag bits, e.g. 0x1 for shapes only,
// 0xFFF for all), and --dump-frame saves the last frame.
// --ratio renders the ball_pit scene at 800x600 as `impulse2d render ball_pit --size 800x600`
// does (600 steps, every 4th a frame, PNG frames written by 2 writer threads), once with
// `--overlays all` and once with `--overlays none`, in turn (the order swapped every pair),
// --repeats times (default 5), and prints the CPU time of all threads per frame of each, the
// every-overlay / shapes-only ratio of each pair with the median and range; then the same for
// the render alone (`FrameRenderer::render`, both overlay sets rendered at each frame's step).
// --state-ratio steps ball_pit to --step (default 400) and renders that one world state
// --frames times (default 60) with every overlay and as often shapes only, in turn, and prints
// the median and lower quartile CPU time of all threads per render of each, their ratio and the
// every-overlay frame's hash: the render alone without the spread of different frames, and a
// check that a change kept the pixels. --only all|none renders one set only, for instruction
// counts: `valgrind --tool=callgrind bench_render --state-ratio --only all --frames N` for N = 2
// and 6, the difference of the totals over 4 is one render's instructions of every thread.
#include "core/world.h"
#include "demos/scene_registry.h"
#include "frames/frame_plan.h"
#include "frames/frame_sequence.h"
#include "frames/scene_camera.h"
#include "frames/view_frame_options.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "render/frame_writer.h"
#include "image/png.h"
#include "scene/overlays.h"
#include "scene/scene_run.h"

#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

constexpr int kWidth = 800;
constexpr int kHeight = 600;
constexpr int kBodies = 1000;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// CPU time used so far by every thread of this process (user + system), milliseconds.
double process_cpu_milliseconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto ms = [](const timeval& t) {
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-3 * static_cast<double>(t.tv_usec);
  };
  return ms(usage.ru_utime) + ms(usage.ru_stime);
}

// A 40 m wide bin with 1000 bodies (circles, oriented boxes, triangles and hexagons, in
// turn) dropped in a grid above its floor.
World make_bin() {
  World world;
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.material = materials::static_ground();
  wall.position = {0.0f, -0.5f};
  world.create_body(wall, make_box({21.0f, 0.5f}));
  wall.position = {-20.5f, 14.5f};
  world.create_body(wall, make_box({0.5f, 15.0f}));
  wall.position = {20.5f, 14.5f};
  world.create_body(wall, make_box({0.5f, 15.0f}));

  const vec2 triangle[3] = {{-0.35f, -0.3f}, {0.35f, -0.3f}, {0.0f, 0.35f}};
  vec2 hexagon[6];
  for (int i = 0; i < 6; ++i) {
    const float angle = 1.0471976f * static_cast<float>(i);
    hexagon[i] = vec2(0.35f * std::cos(angle), 0.35f * std::sin(angle));
  }
  const Shape shapes[4] = {make_circle(0.35f), make_oriented_box({0.3f, 0.3f}), make_polygon(triangle, 3),
                           make_polygon(hexagon, 6)};
  const int columns = 40;
  for (int i = 0; i < kBodies - 3; ++i) {
    BodyDef body;
    const int row = i / columns;
    const int column = i % columns;
    body.position = {-19.5f + static_cast<float>(column) + 0.2f * static_cast<float>(row % 2),
                     0.5f + 0.9f * static_cast<float>(row)};
    body.angle = 0.1f * static_cast<float>(i % 7);
    world.create_body(body, shapes[i % 4]);
  }
  return world;
}

FrameOptions overlay_options(std::uint32_t flags) {
  FrameOptions options;
  options.draw.flags = flags;
  options.draw.impulse_scale = 0.2f;
  return options;
}

HudInfo hud_for(std::int64_t frame) {
  HudInfo info;
  info.scene_name = "bin1000";
  info.step = frame;
  return info;
}

struct Arguments {
  int frames = 60;
  int warmup = 120;
  std::string out;
  std::string dump_frame;
  bool render_only = false;
  std::uint32_t render_only_flags = draw_all;
  bool ratio = false;
  int repeats = 5;
  bool state_ratio = false;
  int step = 400;
  std::string only;  // --state-ratio: "all" or "none" renders that set alone
};

Arguments parse_arguments(int argc, char** argv) {
  Arguments args;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (flag == "--frames" && has_value) {
      args.frames = std::atoi(argv[++i]);
    } else if (flag == "--warmup" && has_value) {
      args.warmup = std::atoi(argv[++i]);
    } else if (flag == "--out" && has_value) {
      args.out = argv[++i];
    } else if (flag == "--dump-frame" && has_value) {
      args.dump_frame = argv[++i];
    } else if (flag == "--render-only") {
      args.render_only = true;
    } else if (flag == "--ratio") {
      args.ratio = true;
    } else if (flag == "--state-ratio") {
      args.state_ratio = true;
    } else if (flag == "--step" && has_value) {
      args.step = std::atoi(argv[++i]);
    } else if (flag == "--only" && has_value) {
      args.only = argv[++i];
    } else if (flag == "--repeats" && has_value) {
      args.repeats = std::atoi(argv[++i]);
    } else if (flag == "--flags" && has_value) {
      args.render_only_flags = static_cast<std::uint32_t>(std::strtoul(argv[++i], nullptr, 0));
    } else {
      std::fprintf(stderr,
                   "usage: %s [--frames N] [--warmup STEPS] [--out DIR] [--dump-frame FILE] [--render-only "
                   "[--flags MASK]]\n       %s --ratio [--repeats N]\n       %s --state-ratio [--step N] "
                   "[--frames N] [--only all|none]\n",
                   argv[0], argv[0], argv[0]);
      std::exit(2);
    }
  }
  if (args.frames < 1 || args.warmup < 0 || args.repeats < 1 || args.step < 0) {
    std::fprintf(stderr, "bench_render: --frames and --repeats must be >= 1, --warmup and --step >= 0\n");
    std::exit(2);
  }
  if (!args.only.empty() && args.only != "all" && args.only != "none") {
    std::fprintf(stderr, "bench_render: --only takes all or none, not '%s'\n", args.only.c_str());
    std::exit(2);
  }
  return args;
}

// Saves `frame` to `path`: a PNG when the name ends in .png, else raw RGBA.
void dump_frame(const Frame& frame, const std::string& path) {
  if (fs::path(path).extension() == ".png") {
    image::save_png(path, frame);
    return;
  }
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(frame.rgba.data()), static_cast<std::streamsize>(frame.rgba.size()));
}

struct EncodeResult {
  double milliseconds = 0.0;  // per frame
  double kilobytes = 0.0;     // per frame
};

EncodeResult measure_encode(const std::vector<Frame>& frames, image::PngCompression encoding) {
  EncodeResult result;
  const Clock::time_point start = Clock::now();
  for (const Frame& frame : frames) result.kilobytes += static_cast<double>(image::encode_png(frame, encoding).size()) / 1024.0;
  result.milliseconds = milliseconds_since(start) / static_cast<double>(frames.size());
  result.kilobytes /= static_cast<double>(frames.size());
  return result;
}

// Simulate, render, encode and write `frames` frames on this thread; frames/s.
double end_to_end_synchronous(World world, FrameRenderer& renderer, const Camera& camera,
                              const FrameOptions& options, int frames, const fs::path& directory,
                              image::PngCompression encoding) {
  Frame frame;
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < frames; ++i) {
    world.step();
    renderer.render(world, camera, options, hud_for(i), frame);
    image::save_png(frame_file_path(directory, "bin1000", i), frame, encoding);
  }
  return 1000.0 * frames / milliseconds_since(start);
}

// Frames/s and CPU milliseconds per frame (all threads) of a run.
struct Throughput {
  double frames_per_second = 0.0;
  double cpu_ms_per_frame = 0.0;
};

// The same with the writer's worker threads encoding while the next frame is made.
Throughput end_to_end_async(World world, FrameRenderer& renderer, const Camera& camera, const FrameOptions& options,
                            int frames, const fs::path& directory, int workers) {
  FrameWriterOptions writer_options;
  writer_options.directory = directory;
  writer_options.scene_name = "bin1000";
  writer_options.worker_threads = workers;
  writer_options.queue_capacity = 4;
  const double cpu_start = process_cpu_milliseconds();
  const Clock::time_point start = Clock::now();
  AsyncFrameWriter writer(writer_options);
  for (int i = 0; i < frames; ++i) {
    world.step();
    Frame frame = writer.take_spare_frame();
    renderer.render(world, camera, options, hud_for(i), frame);
    writer.submit(i, std::move(frame));
  }
  writer.finish();
  return Throughput{1000.0 * frames / milliseconds_since(start),
                    (process_cpu_milliseconds() - cpu_start) / static_cast<double>(frames)};
}

// Everything measured for one set of overlay flags.
struct Measured {
  double render_ms = 0.0;
  double render_cpu_ms = 0.0;
  EncodeResult small;
  EncodeResult fast;
  double baseline_fps = 0.0;
  double fast_sync_fps = 0.0;
  Throughput async1;
  Throughput async2;
};


// --ratio: the every-overlay frame against the shapes-only frame of ball_pit, 800x600.
constexpr const char* kRatioScene = "ball_pit";

// CPU milliseconds of all threads per frame of `impulse2d render ball_pit --size 800x600
// --overlays <overlays>`: a fresh run, rendered and written to `directory` by 2 writer threads.
double end_to_end_cpu_per_frame(const demos::Scene& scene, const std::string& overlays, const fs::path& directory) {
  demos::SceneRun run(scene, demos::Params(scene.params));
  const demos::FramePlan plan = demos::plan_frames(scene.view.frames, scene.view.steps);
  demos::FrameSequenceOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.draw = scene.view.draw;
  options.draw.flags = demos::parse_overlays(overlays);
  options.directory = directory;
  options.clean = true;
  const double cpu_start = process_cpu_milliseconds();
  const demos::FrameSequenceResult result = demos::render_frame_sequence(run, plan, options, nullptr);
  return (process_cpu_milliseconds() - cpu_start) / static_cast<double>(result.frame_count);
}

// CPU milliseconds of all threads per `FrameRenderer::render` of ball_pit's frames, with
// every overlay (`all`) and shapes only (`none`), both rendered at each frame's step, the
// order swapped every frame.
struct RenderPair {
  double all = 0.0;
  double none = 0.0;
};

// The frame options of `scene`'s view for `run`, with every overlay (first) and shapes only
// (second).
std::array<FrameOptions, 2> all_and_none_options(const demos::SceneRun& run, const demos::Scene& scene) {
  DebugDrawOptions draw = scene.view.draw;
  std::array<FrameOptions, 2> options = {demos::view_frame_options(run, draw, Theme::Light),
                                         demos::view_frame_options(run, draw, Theme::Light)};
  options[0].draw.flags = demos::parse_overlays("all");
  options[1].draw.flags = demos::parse_overlays("none");
  return options;
}

RenderPair render_cpu_per_frame(const demos::Scene& scene) {
  demos::SceneRun run(scene, demos::Params(scene.params));
  const demos::FramePlan plan = demos::plan_frames(scene.view.frames, scene.view.steps);
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = demos::run_camera(run, kWidth, kHeight);
  std::array<FrameOptions, 2> options = all_and_none_options(run, scene);
  HudInfo hud;
  hud.scene_name = demos::scene_title(scene);
  Frame frame;
  double cpu[2] = {0.0, 0.0};
  for (std::size_t i = 0; i < plan.frames.size(); ++i) {
    while (run.step_count() < plan.frames[i]) run.step();
    hud.step = plan.frames[i];
    hud.frame_index = static_cast<std::int64_t>(i);
    for (int turn = 0; turn < 2; ++turn) {
      const int which = (turn + static_cast<int>(i)) % 2;
      demos::update_view_frame(run, options[which], hud);
      const double cpu_start = process_cpu_milliseconds();
      renderer.render(run.world(), demos::frame_camera(camera, run), options[which], hud, frame);
      cpu[which] += process_cpu_milliseconds() - cpu_start;
    }
  }
  const double frames = static_cast<double>(plan.frames.size());
  return RenderPair{cpu[0] / frames, cpu[1] / frames};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

// Prints one table row per pair and the ratios' median and range.
void print_pairs(const char* what, const std::vector<RenderPair>& pairs) {
  std::vector<double> all;
  std::vector<double> none;
  std::vector<double> ratios;
  std::printf("\n%s, CPU of all threads, ms/frame\n\n| pair | every overlay | shapes only | ratio |\n|---|---|---|---|\n",
              what);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    all.push_back(pairs[i].all);
    none.push_back(pairs[i].none);
    ratios.push_back(pairs[i].all / pairs[i].none);
    std::printf("| %zu | %.2f | %.2f | %.2f |\n", i + 1, pairs[i].all, pairs[i].none, ratios.back());
  }
  std::printf("| median | %.2f | %.2f | **%.2f** [%.2f-%.2f] |\n", median(all), median(none), median(ratios),
              *std::min_element(ratios.begin(), ratios.end()), *std::max_element(ratios.begin(), ratios.end()));
}

int run_ratio(const Arguments& args, const fs::path& out) {
  const demos::Scene& scene = *demos::find_builtin_scene(kRatioScene);
  std::printf("bench_render --ratio: %s, %dx%d, %s frames of %lld steps, %d pairs (order swapped every pair); "
              "%u hardware threads, load average at start: ",
              kRatioScene, kWidth, kHeight, scene.view.frames.c_str(), static_cast<long long>(scene.view.steps),
              args.repeats, std::thread::hardware_concurrency());
  double load[1] = {0.0};
  if (getloadavg(load, 1) == 1) std::printf("%.2f\n", load[0]);
  std::vector<RenderPair> end_to_end;
  for (int pair = 0; pair < args.repeats; ++pair) {
    RenderPair measured;
    for (int turn = 0; turn < 2; ++turn) {
      const bool all = (turn + pair) % 2 == 0;
      (all ? measured.all : measured.none) = end_to_end_cpu_per_frame(scene, all ? "all" : "none", out);
    }
    end_to_end.push_back(measured);
  }
  print_pairs("End to end (simulate, render, PNG on 2 writer threads, as `impulse2d render ball_pit --size 800x600`)",
              end_to_end);
  std::vector<RenderPair> render_only;
  for (int pair = 0; pair < args.repeats; ++pair) render_only.push_back(render_cpu_per_frame(scene));
  print_pairs("Render alone (FrameRenderer::render)", render_only);
  return 0;
}
// --state-ratio: one world state of ball_pit rendered with every overlay and shapes only, in turn.
int run_state_ratio(const Arguments& args) {
  const demos::Scene& scene = *demos::find_builtin_scene(kRatioScene);
  demos::SceneRun run(scene, demos::Params(scene.params));
  while (run.step_count() < args.step) run.step();
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = demos::frame_camera(demos::run_camera(run, kWidth, kHeight), run);
  std::array<FrameOptions, 2> options = all_and_none_options(run, scene);
  HudInfo hud;
  hud.scene_name = demos::scene_title(scene);
  hud.step = args.step;
  const bool renders[2] = {args.only != "none", args.only != "all"};
  Frame frame;
  std::uint64_t all_hash = 0;
  for (int which = 0; which < 2; ++which) {  // the first render of each set compiles its shaders
    if (!renders[which]) continue;
    demos::update_view_frame(run, options[which], hud);
    renderer.render(run.world(), camera, options[which], hud, frame);
    if (which == 0) all_hash = frame.hash();
  }
  std::vector<double> cpu[2];
  for (int i = 0; i < args.frames; ++i) {
    for (int turn = 0; turn < 2; ++turn) {
      const int which = (turn + i) % 2;
      if (!renders[which]) continue;
      demos::update_view_frame(run, options[which], hud);
      const double cpu_start = process_cpu_milliseconds();
      renderer.render(run.world(), camera, options[which], hud, frame);
      cpu[which].push_back(process_cpu_milliseconds() - cpu_start);
    }
  }
  const auto quartile = [](std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 4];
  };
  std::printf("bench_render --state-ratio: %s at step %d, %dx%d, %d renders of each set, in turn; %u hardware threads\n",
              kRatioScene, args.step, kWidth, kHeight, args.frames, std::thread::hardware_concurrency());
  std::printf("\nFrameRenderer::render of one state, CPU of all threads, ms/render\n\n| overlays | median | lower quartile |\n|---|---|---|\n");
  const char* names[2] = {"every overlay", "shapes only"};
  for (int which = 0; which < 2; ++which) {
    if (renders[which]) std::printf("| %s | %.2f | %.2f |\n", names[which], median(cpu[which]), quartile(cpu[which]));
  }
  if (renders[0] && renders[1]) {
    std::printf("| ratio | **%.3f** | %.3f |\n", median(cpu[0]) / median(cpu[1]), quartile(cpu[0]) / quartile(cpu[1]));
  }
  if (renders[0]) std::printf("\nevery-overlay frame hash: %016llx\n", static_cast<unsigned long long>(all_hash));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Arguments args = parse_arguments(argc, argv);
  if (args.state_ratio) return run_state_ratio(args);
  const bool temporary_output = args.out.empty();
  const fs::path out = temporary_output
                           ? fs::temp_directory_path() / ("impulse2d-bench-render-" + std::to_string(::getpid()))
                           : fs::path(args.out);
  fs::create_directories(out);
  if (args.ratio) {
    const int status = run_ratio(args, out);
    if (temporary_output) fs::remove_all(out);
    return status;
  }

  World world = make_bin();
  for (int i = 0; i < args.warmup; ++i) world.step();
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = Camera::fit(world_bounds(world), kWidth, kHeight, 10.0f);
  if (args.render_only) {
    const FrameOptions options = overlay_options(args.render_only_flags);
    Frame frame;
    const double cpu_start = process_cpu_milliseconds();
    const Clock::time_point render_start = Clock::now();
    for (int i = 0; i < args.frames; ++i) {
      world.step();
      renderer.render(world, camera, options, hud_for(i), frame);
    }
    std::printf("bench_render --render-only: %d frames (overlay flags 0x%X), %.2f ms/frame, CPU %.2f ms/frame\n",
                args.frames, args.render_only_flags, milliseconds_since(render_start) / args.frames,
                (process_cpu_milliseconds() - cpu_start) / args.frames);
    if (!args.dump_frame.empty()) dump_frame(frame, args.dump_frame);
    if (temporary_output) fs::remove_all(out);
    return 0;
  }

  // Simulation alone.
  World timed = world;
  Clock::time_point start = Clock::now();
  for (int i = 0; i < args.frames; ++i) timed.step();
  const double step_ms = milliseconds_since(start) / args.frames;

  std::vector<Measured> results;
  std::size_t contacts = 0;
  for (const std::uint32_t flags : {static_cast<std::uint32_t>(draw_all), static_cast<std::uint32_t>(draw_shapes)}) {
    const FrameOptions options = overlay_options(flags);
    Measured m;
    // Rendering alone (a step between frames, not timed); keeps 20 frames for encoding.
    std::vector<Frame> frames;
    World rendered = world;
    Frame frame;
    contacts = 0;
    for (int i = 0; i < args.frames; ++i) {
      rendered.step();
      contacts += rendered.contacts().size();
      const double cpu_start = process_cpu_milliseconds();
      start = Clock::now();
      renderer.render(rendered, camera, options, hud_for(i), frame);
      m.render_ms += milliseconds_since(start);
      m.render_cpu_ms += process_cpu_milliseconds() - cpu_start;
      if (i < 20) frames.push_back(frame);
    }
    m.render_ms /= args.frames;
    m.render_cpu_ms /= args.frames;
    if (!args.dump_frame.empty() && flags == draw_all) dump_frame(frames.back(), args.dump_frame);
    m.small = measure_encode(frames, image::PngCompression::Small);
    m.fast = measure_encode(frames, image::PngCompression::Fast);
    m.baseline_fps = end_to_end_synchronous(world, renderer, camera, options, args.frames, out, image::PngCompression::Small);
    m.fast_sync_fps = end_to_end_synchronous(world, renderer, camera, options, args.frames, out, image::PngCompression::Fast);
    m.async1 = end_to_end_async(world, renderer, camera, options, args.frames, out, 1);
    m.async2 = end_to_end_async(world, renderer, camera, options, args.frames, out, 2);
    results.push_back(m);
  }

  std::printf("bench_render: %d bodies, %dx%d, HUD + legend, %d frames after %d warm-up steps\n", world.body_count(),
              kWidth, kHeight, args.frames, args.warmup);
  std::printf("renderer: %s; %u hardware threads; %.0f contacts per frame; World::step %.2f ms\n\n",
              renderer.fingerprint().c_str(), std::thread::hardware_concurrency(),
              static_cast<double>(contacts) / args.frames, step_ms);
  const Measured& all = results[0];
  const Measured& shapes = results[1];
  std::printf("| measure | all overlays | shapes only |\n|---|---|---|\n");
  std::printf("| render (draw + rasterise + read back), ms/frame | %.2f | %.2f |\n", all.render_ms, shapes.render_ms);
  std::printf("| render, CPU of all threads, ms/frame | %.2f | %.2f |\n", all.render_cpu_ms, shapes.render_cpu_ms);
  std::printf("| PNG encode, small (libdeflate 12, baseline), ms/frame | %.2f (%.0f KB) | %.2f (%.0f KB) |\n",
              all.small.milliseconds, all.small.kilobytes, shapes.small.milliseconds, shapes.small.kilobytes);
  std::printf("| PNG encode, fast (libdeflate 1), ms/frame | %.2f (%.0f KB) | %.2f (%.0f KB) |\n",
              all.fast.milliseconds, all.fast.kilobytes, shapes.fast.milliseconds, shapes.fast.kilobytes);
  std::printf("| fast vs small: speed-up, size ratio | %.2fx, %.2f | %.2fx, %.2f |\n",
              all.small.milliseconds / all.fast.milliseconds, all.fast.kilobytes / all.small.kilobytes,
              shapes.small.milliseconds / shapes.fast.milliseconds, shapes.fast.kilobytes / shapes.small.kilobytes);
  const auto row = [](const char* name, double value_all, double base_all, double value_shapes, double base_shapes) {
    std::printf("| %s, frames/s | %.1f (%.2fx) | %.1f (%.2fx) |\n", name, value_all, value_all / base_all, value_shapes,
                value_shapes / base_shapes);
  };
  row("end to end, 1 thread, small PNG (baseline)", all.baseline_fps, all.baseline_fps, shapes.baseline_fps,
      shapes.baseline_fps);
  row("end to end, 1 thread, fast PNG", all.fast_sync_fps, all.baseline_fps, shapes.fast_sync_fps, shapes.baseline_fps);
  row("end to end, fast PNG on 1 writer thread", all.async1.frames_per_second, all.baseline_fps,
      shapes.async1.frames_per_second, shapes.baseline_fps);
  row("end to end, fast PNG on 2 writer threads", all.async2.frames_per_second, all.baseline_fps,
      shapes.async2.frames_per_second, shapes.baseline_fps);
  std::printf("| the same, CPU of all threads, ms/frame | %.1f | %.1f |\n", all.async2.cpu_ms_per_frame,
              shapes.async2.cpu_ms_per_frame);

  if (temporary_output) fs::remove_all(out);
  return 0;
}

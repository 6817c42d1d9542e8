// bench_v3: impulse2d beside Box2D v3 at equal vector width, in the same run (issue 33). For
// each scene (bench_compare's large_pyramid, many_pyramids and ball_pit) it runs `rounds`
// rounds, each alternating
//   impulse2d default with WorldSettings::solver_lanes = 4, Box2D v3's SSE2 build,
//   impulse2d default with 8 lanes,                       Box2D v3's AVX2 build
// (the AVX2 pair skipped, with a note, on a CPU without AVX2). impulse2d runs in this process
// with exactly bench_compare's default settings but the lane count (compare::impulse2d_settings);
// v3 runs in its runners (bench_v3_runner_sse2/_avx2, started with posix_spawn, their one line
// parsed strictly). Both are timed by the same loop: `warmup` untimed steps, then `steps` steps
// each timed alone by the thread's CPU time, the median kept. Per scene and width it prints
// every pair's ratio (ours / v3), their median and [min-max], whether every pair is below 1
// and whether the median meets the goal (<= 0.9), and both engines' stability figures, with
// the v3 commit in every heading. With --scale it runs bench_compare's scaling series instead
// (compare::scaling_sizes, up to --scale-max bodies): each round runs every size, fewest
// bodies first, alternating the same four at each, and it prints per width and size both
// engines' µs of CPU per body per step, their growth from the smallest size and the ratio
// ours / v3 (v3_scale.h). --out DIR also writes DIR/table.md (temporary file, then renamed: all
// or nothing). Configured without Box2D v3 (bench/v3.cmake) it says how to configure it and
// exits 2. Exit status: 0 measured, 1 a run failed, 2 bad arguments or no v3.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/compare/compare_run.h"
#include "bench/compare/world_simulation.h"
#include "bench/v3/v3_options.h"
#include "bench/v3/v3_pairs.h"
#include "bench/v3/v3_protocol.h"
#include "bench/v3/v3_scale.h"

extern char** environ;

using namespace impulse2d;
using namespace impulse2d::bench_v3;

#ifdef IMPULSE2D_V3_COMMIT
namespace {

std::string first_line(const char* path, const char* prefix) {
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind(prefix, 0) == 0) return line;
  }
  return "";
}

std::string cpu_model() {
  const std::string line = first_line("/proc/cpuinfo", "model name");
  const std::size_t colon = line.find(':');
  return colon == std::string::npos ? "unknown CPU" : line.substr(colon + 2);
}

std::string load_average() {
  std::istringstream fields(first_line("/proc/loadavg", ""));
  std::string one, five, fifteen;
  fields >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// impulse2d's default (bench_compare's settings) at `lanes` lanes, one run of `scene`.
RunResult run_impulse2d(const compare::CompareScene& scene, int lanes, int warmup, int steps) {
  WorldSettings settings = compare::impulse2d_settings(scene, lab::LabMethod{});
  settings.solver_lanes = lanes;
  const double heap_before = heap_in_use();
  compare::WorldSimulation simulation(scene, settings);
  RunResult result;
  result.scene = scene.name;
  result.steps = steps;
  result.warmup = warmup;
  const std::vector<double> times = timed_steps([&] { simulation.step(); }, warmup, steps);
  result.heap_bytes = heap_in_use() - heap_before;
  result.median_ms = median(times);
  result.min_ms = *std::min_element(times.begin(), times.end());
  std::vector<lab::BodyState> states;
  simulation.read_states(states);
  judge(scene, states, result);
  return result;
}

// Starts `runner` (no shell) on `scene`, reads its stdout and checks every answer; throws
// `std::runtime_error` naming the runner on any failure.
RunResult run_runner(const std::string& runner, const std::string& width, const std::string& commit,
                     const std::string& scene, int warmup, int steps) {
  const std::vector<std::string> arguments{runner, "--scene", scene, "--steps", std::to_string(steps),
                                           "--warmup", std::to_string(warmup)};
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("runner " + runner + ": pipe: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_ends[1]);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, runner.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_ends[1]);
  if (spawned != 0) {
    close(pipe_ends[0]);
    throw std::runtime_error("runner " + runner + " did not start: " + std::strerror(spawned));
  }
  std::string output;
  char buffer[4096];
  while (true) {
    const ssize_t got = read(pipe_ends[0], buffer, sizeof buffer);
    if (got > 0) {
      output.append(buffer, static_cast<std::size_t>(got));
    } else if (got == 0 || errno != EINTR) {
      break;
    }
  }
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("runner " + runner + ": waitpid: " + std::strerror(errno));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("runner " + runner + " failed (" +
                             (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) +
                             ") on " + scene);
  }
  if (output.empty() || output.back() != '\n' || output.find('\n') != output.size() - 1) {
    throw std::runtime_error("runner " + runner + " printed not exactly one line: '" + output + "'");
  }
  RunResult result = parse_runner_line(output, runner);
  if (result.scene != scene || result.width != width || result.commit != commit ||
      result.steps != steps || result.warmup != warmup) {
    throw std::runtime_error("runner " + runner + " answered for another run (asked " + scene + " " + width +
                             " " + commit + " steps=" + std::to_string(steps) + " warmup=" +
                             std::to_string(warmup) + "): '" + output + "'");
  }
  return result;
}

// Writes DIR/table.md with `write` through a temporary file renamed at the end; nothing is left
// behind when `write` throws or the file cannot be written.
void write_all_or_nothing(const std::string& directory, const std::function<void(std::ostream&)>& write) {
  std::filesystem::create_directories(directory);
  const std::filesystem::path final_path = std::filesystem::path(directory) / "table.md";
  const std::filesystem::path temporary = std::filesystem::path(directory) / ".table.md.tmp";
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    try {
      write(file);
    } catch (...) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw;
    }
    file.flush();
    if (!file) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error("cannot write " + temporary.string());
    }
  }
  std::filesystem::rename(temporary, final_path);
  std::cout << "\nwrote " << final_path.string() << "\n";
}

// bench_v3 --scale: every round runs each size of the series, fewest bodies first, alternating
// impulse2d 4 lanes, v3 SSE2, impulse2d 8 lanes, v3 AVX2 at each.
ScaleReport run_scale(const Options& options, const std::string& commit, bool avx2) {
  const std::vector<compare::ScalingSize> sizes = scale_sizes(options);
  ScaleReport report;
  report.commit = commit;
  report.rounds = options.rounds;
  report.steps = measured_steps(options, scaling_steps);
  report.warmup = options.warmup;
  report.widths = {ScaleWidth{"impulse2d 4 lanes", "Box2D v3 SSE2", {}, ""},
                   ScaleWidth{"impulse2d 8 lanes", "Box2D v3 AVX2", {}, avx2 ? "" : "this CPU has no AVX2"}};
  for (ScaleWidth& width : report.widths) {
    if (!width.skipped.empty()) continue;
    for (const compare::ScalingSize& size : sizes) width.points.push_back(ScalePoint{size.bodies, {}, {}});
  }
  const char* const runners[] = {IMPULSE2D_V3_RUNNER_SSE2, IMPULSE2D_V3_RUNNER_AVX2};
  const char* const widths[] = {"sse2", "avx2"};
  for (int round = 1; round <= options.rounds; ++round) {
    for (std::size_t s = 0; s < sizes.size(); ++s) {
      const compare::CompareScene scene = compare::scaling_scene(sizes[s].pyramids, report.steps);
      for (std::size_t w = 0; w < 2; ++w) {
        ScaleWidth& width = report.widths[w];
        if (!width.skipped.empty()) continue;
        ScalePoint& point = width.points[s];
        point.ours_runs.push_back(run_impulse2d(scene, w == 0 ? 4 : 8, report.warmup, report.steps));
        point.theirs_runs.push_back(
            run_runner(runners[w], widths[w], commit, scene.name, report.warmup, report.steps));
        const double ours = micros_per_body(point.ours_runs.back().median_ms, point.bodies);
        const double theirs = micros_per_body(point.theirs_runs.back().median_ms, point.bodies);
        std::fprintf(stderr, "bench_v3: %s round %d: %s %.3f us/body, %s %.3f us/body, ratio %.3f\n",
                     scene.name.c_str(), round, width.ours.c_str(), ours, width.theirs.c_str(), theirs,
                     ours / theirs);
      }
    }
  }
  return report;
}

}  // namespace
#endif

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse_options(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& error) {
    std::fprintf(stderr, "bench_v3: %s\n%s\n", error.what(), usage_text());
    return 2;
  }
  if (options.help) {
    std::printf("%s\n", usage_text());
    return 0;
  }
#ifndef IMPULSE2D_V3_COMMIT
  std::fprintf(stderr,
               "bench_v3: this build has no Box2D v3. Configure with a v3 source tree (never "
               "vendored; docs/bench/v3.md):\n"
               "  cmake -S . -B build -DIMPULSE2D_BOX2D_V3_SOURCE=/path/to/box2d "
               "[-DIMPULSE2D_BOX2D_V3_COMMIT=<40-hex commit, when it is not a git checkout>]\n"
               "  cmake --build build --target bench_v3\n");
  return 2;
#else
  const std::string commit = IMPULSE2D_V3_COMMIT;
  const bool avx2 = __builtin_cpu_supports("avx2");
  Report report;
  report.commit = commit;
  report.machine = cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) + " cores";
  report.rounds = options.rounds;
  for (int i = 0; i < argc; ++i) report.command += (i == 0 ? "" : " ") + std::string(argv[i]);
  const std::string load_before = load_average();
  if (!avx2) std::cout << "note: this CPU has no AVX2: the 8-lane / AVX2 pairs are skipped\n";
  if (options.scale) {
    try {
      ScaleReport scale = run_scale(options, commit, avx2);
      scale.machine = report.machine;
      scale.command = report.command;
      scale.load = load_before + " / " + load_average();
      write_scale_report(std::cout, scale, false);
      std::cout.flush();
      if (!options.out.empty()) {
        write_all_or_nothing(options.out, [&](std::ostream& file) { write_scale_report(file, scale, true); });
      }
    } catch (const std::exception& error) {
      std::fprintf(stderr, "bench_v3: %s\n", error.what());
      return 1;
    }
    return 0;
  }
  try {
    for (const std::string& name : options.scenes) {
      const compare::CompareScene scene = scene_by_name(name);
      SceneSeries series;
      series.scene = name;
      series.bodies = scene.dynamic_count;
      series.steps = measured_steps(options, scene.steps);
      series.warmup = options.warmup;
      series.judge = scene.judge;
      series.widths = {WidthSeries{"impulse2d 4 lanes", "Box2D v3 SSE2", {}, {}, ""},
                       WidthSeries{"impulse2d 8 lanes", "Box2D v3 AVX2", {}, {}, avx2 ? "" : "this CPU has no AVX2"}};
      const char* const runners[] = {IMPULSE2D_V3_RUNNER_SSE2, IMPULSE2D_V3_RUNNER_AVX2};
      const char* const widths[] = {"sse2", "avx2"};
      for (int round = 1; round <= options.rounds; ++round) {
        for (std::size_t w = 0; w < 2; ++w) {
          WidthSeries& width = series.widths[w];
          if (!width.skipped.empty()) continue;
          width.ours_runs.push_back(run_impulse2d(scene, w == 0 ? 4 : 8, series.warmup, series.steps));
          width.theirs_runs.push_back(run_runner(runners[w], widths[w], commit, name, series.warmup, series.steps));
          std::fprintf(stderr, "bench_v3: %s round %d: %s %.3f ms, %s %.3f ms, ratio %.3f\n", name.c_str(), round,
                       width.ours.c_str(), width.ours_runs.back().median_ms, width.theirs.c_str(),
                       width.theirs_runs.back().median_ms,
                       width.ours_runs.back().median_ms / width.theirs_runs.back().median_ms);
        }
      }
      report.scenes.push_back(series);
    }
    report.load = load_before + " / " + load_average();
    write_report(std::cout, report, false);
    std::cout.flush();
    if (!options.out.empty()) {
      write_all_or_nothing(options.out, [&](std::ostream& file) { write_report(file, report, true); });
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_v3: %s\n", error.what());
    return 1;
  }
  return 0;
#endif
}

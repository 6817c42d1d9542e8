// bench_compare: impulse2d against Box2D 2.4.1 and Chipmunk 7 on the same scenes in the same
// run (issue 13). Scenes: the 20-row pyramid, Box2D v3's large_pyramid (5050 boxes) and
// many_pyramids (400 pyramids, 22000 boxes), a ball pit (5000 circles), rain (2000 bodies
// recycled as they fall off a field), and a scaling series of many pyramids of about 1k, 2k,
// 5k, 10k, 20k, 50k and 100k boxes. Engines: impulse2d's default settings, impulse2d's
// accumulated solver (16 iterations), Box2D 2.4.1 (8/3 iterations), Chipmunk 7 (10
// iterations); 1/60 s, sleeping off, one thread. Prints per scene the median CPU ms per step of
// every engine (interleaved in blocks of 20 steps), the ratios ours/theirs and beside every
// speed the stability figures (stability.h); for the scaling series also the cost per body and
// the memory per body of every engine (issue 33). Writes DIR/results.csv, DIR/table.md,
// DIR/scaling.csv, DIR/scale.csv, DIR/scale.md and the log-log chart DIR/bench_scaling.png.
//
// Usage: bench_compare [--out DIR] [--quick | --smoke] [--only NAME,NAME... | --scale]
//                      [--scale-max BODIES] [--peers-max BODIES] [--steps N]
//   full:        the step counts below, scaling series up to 100100 bodies
//   --quick:     a fifth of the steps, scaling series up to 20020 bodies
//   --smoke:     tiny scenes and 10 steps, seconds: proves the command runs (a ctest), not timing
//   --only:      just the named scenes (the chart needs the scaling_* ones)
//   --scale:     just the scaling series
//   --scale-max: the scaling series' largest size, bodies (its points are 990, 1980, 5005,
//                10010, 20020, 50050, 100100)
//   --peers-max: leave every engine but impulse2d's default out of scenes with more bodies
//                (default: none left out; the others take about 4 of the full run's minutes
//                at 50k and 100k)
//   --steps:     every scene runs N steps instead (for profiling one size)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/compare/compare_chart.h"
#include "bench/compare/compare_report.h"
#include "bench/compare/compare_run.h"
#include "bench/compare/compare_scale.h"
#include "bench/compare/compare_scene.h"

using namespace impulse2d::compare;

namespace {

enum class Size { Full, Quick, Smoke };

// The scenes and their full step counts: Box2D v3's own for its scenes (large_pyramid 500,
// many_pyramids 200), 600 for the small pyramid, 300 for the ball pit (5 s: the balls have
// landed), 600 for rain (10 s: the field is full and bodies recycle), 100 for each scaling
// point (the pyramids at rest, every step alike). The scaling series stops at the largest
// size not above `scale_max` bodies.
std::vector<CompareScene> scenes(Size size, int scale_max) {
  if (size == Size::Smoke) {
    std::vector<CompareScene> list{pyramid_scene("pyramid_5", 5, 10),
                                   many_pyramids_scene("many_pyramids", 4, 2, 3, 10),
                                   ball_pit_scene("ball_pit", 60, 10, 10),
                                   rain_scene("rain", 40, 10)};
    for (const int count : {1, 3}) {
      list.push_back(many_pyramids_scene("scaling_" + std::to_string(count), count, 2, 3, 10));
      list.back().scaling = true;
    }
    return list;
  }
  const int divisor = size == Size::Quick ? 5 : 1;
  std::vector<CompareScene> list{pyramid_scene("pyramid_20", 20, 600 / divisor),
                                 pyramid_scene("large_pyramid", 100, 500 / divisor),
                                 many_pyramids_scene("many_pyramids", 400, 20, 10, 200 / divisor),
                                 ball_pit_scene("ball_pit", 5000, 100, 300 / divisor),
                                 rain_scene("rain", 2000, 600 / divisor)};
  for (const ScalingSize& point : scaling_sizes()) {
    if (point.bodies > scale_max) break;
    list.push_back(scaling_scene(point.pyramids, 100 / divisor));
  }
  return list;
}

std::string cpu_model() {
  std::ifstream file("/proc/cpuinfo");
  std::string line;
  while (std::getline(file, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

const char* const usage_line =
    "usage: bench_compare [--out DIR] [--quick | --smoke] [--only NAME,NAME... | --scale]\n"
    "                     [--scale-max BODIES] [--peers-max BODIES] [--steps N]";

// Memory of each engine's world for the scaling series: built alone, stepped this many times.
int memory_steps(Size size) { return size == Size::Smoke ? 2 : 10; }

// A positive whole number (of bodies or steps), or -1.
int parse_count(const std::string& text) {
  try {
    std::size_t used = 0;
    const long value = std::stol(text, &used);
    if (used != text.size() || value <= 0 || value > 100000000) return -1;
    return static_cast<int>(value);
  } catch (const std::exception&) {
    return -1;
  }
}

int usage(const char* message) {
  std::fprintf(stderr, "bench_compare: %s\n%s\n", message, usage_line);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string directory = "out/bench_compare";
  Size size = Size::Full;
  std::string only;  // ",a,b," or empty for every scene
  bool scale_only = false;
  int scale_max = -1;  // bodies; -1: the mode's own
  int peers_max = -1;  // bodies; -1: the mode's own
  int steps = -1;      // -1: each scene's own
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      directory = argv[++i];
    } else if (arg == "--only" && i + 1 < argc) {
      only = std::string(",") + argv[++i] + ",";
    } else if (arg == "--scale") {
      scale_only = true;
    } else if ((arg == "--scale-max" || arg == "--peers-max" || arg == "--steps") && i + 1 < argc) {
      const int value = parse_count(argv[++i]);
      if (value < 0) return usage((arg + " wants a positive whole number, not " + argv[i]).c_str());
      (arg == "--scale-max" ? scale_max : arg == "--peers-max" ? peers_max : steps) = value;
    } else if (arg == "--quick" || arg == "--smoke") {
      if (size != Size::Full) return usage("--quick and --smoke exclude each other");
      size = arg == "--quick" ? Size::Quick : Size::Smoke;
    } else if (arg == "--help" || arg == "-h") {
      std::printf("%s\n", usage_line);
      return 0;
    } else {
      return usage(("unknown argument " + arg).c_str());
    }
  }
  if (scale_only && !only.empty()) return usage("--only and --scale exclude each other");
  if (scale_max < 0) scale_max = size == Size::Quick ? 20020 : 100100;
  if (peers_max < 0) peers_max = std::numeric_limits<int>::max();
  try {
    std::filesystem::create_directories(directory);
    std::vector<std::string> notes;
    const std::vector<Contender> engines = contenders(notes);
    const int block = size == Size::Smoke ? 5 : 20;
    const std::string machine = cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) +
                                " cores; one thread; steps of 1/60 s, sleeping off";
    std::cout << "bench_compare: impulse2d against its peers, the same scenes in the same run\n"
              << "machine: " << machine << ", gravity -10 m/s^2\n"
              << "ms/step: CPU time of each step, median; engines interleaved in blocks of "
              << block << " steps\n"
              << "stability: sag = largest drop of a pyramid's top box; side = largest sideways "
                 "move of a box; moved = boxes moved sideways > 0.1 m or turned > 5 degrees; "
                 "depth = deepest overlap of any two bodies (largest of 6 samples); out = balls "
                 "outside the pit at the end / recyc = rain bodies recycled\n";
    for (const std::string& note : notes) std::cout << "note: " << note << "\n";
    std::vector<SceneResult> results;
    std::vector<CompareScene> chosen;
    for (CompareScene& scene : scenes(size, scale_max)) {
      const bool wanted = scale_only ? scene.scaling
                                     : only.empty() || only.find("," + scene.name + ",") != std::string::npos;
      if (!wanted) continue;
      if (steps > 0) scene.steps = steps;
      chosen.push_back(std::move(scene));
    }
    if (chosen.empty()) {
      std::string names;
      for (const CompareScene& scene : scenes(size, scale_max)) names += " " + scene.name;
      return usage(("--only names none of the scenes:" + names).c_str());
    }
    for (const CompareScene& scene : chosen) {
      if (scene.dynamic_count > peers_max) {
        std::cout << "note: scenes of more than " << peers_max
                  << " bodies run impulse2d's default only (--peers-max)\n";
        break;
      }
    }
    for (const CompareScene& scene : chosen) {
      const auto start = std::chrono::steady_clock::now();
      SceneResult result{scene.name, scene.description, scene.judge, scene.dynamic_count,
                         scene.steps, scene.scaling, {}, 0.0};
      // The first contender is impulse2d's default: it runs at every size.
      std::vector<bool> included(engines.size(), true);
      for (std::size_t e = 1; e < engines.size(); ++e) included[e] = scene.dynamic_count <= peers_max;
      result.outcomes = run_interleaved(scene, engines, included, scene.steps, block);
      if (scene.scaling) {
        for (std::size_t e = 0; e < engines.size(); ++e) {
          if (included[e]) result.outcomes[e].memory = measure_memory(scene, engines[e], memory_steps(size));
        }
      }
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      print_scene_table(std::cout, engines, result);
      std::cout.flush();
      results.push_back(result);
    }
    print_ratios(std::cout, engines, results);
    print_scale_summary(std::cout, engines, results);
    const std::filesystem::path out(directory);
    {
      std::ofstream csv(out / "results.csv", std::ios::binary | std::ios::trunc);
      write_csv(csv, engines, results);
      std::ofstream markdown(out / "table.md", std::ios::binary | std::ios::trunc);
      write_markdown(markdown, engines, results);
      if (!csv || !markdown) throw std::runtime_error("cannot write into " + directory);
    }
    write_scale_files(directory, engines, results, machine);
    std::string why;
    const std::string chart = write_scaling_chart(directory, engines, results, why);
    std::cout << "\nwrote " << (out / "results.csv").string() << ", " << (out / "table.md").string();
    const bool scaled = std::any_of(results.begin(), results.end(),
                                    [](const SceneResult& result) { return result.scaling; });
    if (scaled) std::cout << ", " << (out / "scale.md").string();
    if (!chart.empty()) std::cout << ", " << chart;
    std::cout << "\n";
    if (chart.empty()) std::cout << "no chart: " << why << "\n";
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_compare: %s\n", error.what());
    return 1;
  }
  return 0;
}

// bench_compare: impulse2d against Box2D 2.4.1 and Chipmunk 7 on the same scenes in the same
// run (issue 13). Scenes: the 20-row pyramid, Box2D v3's large_pyramid (5050 boxes) and
// many_pyramids (400 pyramids, 22000 boxes), a ball pit (5000 circles), rain (2000 bodies
// recycled as they fall off a field), and a scaling series of many pyramids of about 1k, 2k,
// 5k, 10k and 20k boxes. Engines: impulse2d's default settings, impulse2d's soft step (4
// substeps x 1 iteration), Box2D 2.4.1 (8/3 iterations), Chipmunk 7 (10 iterations); 1/60 s,
// sleeping off, one thread. Prints per scene the median CPU ms per step of every engine
// (interleaved in blocks of 20 steps), the ratios ours/theirs and beside every speed the
// stability figures (stability.h); writes DIR/results.csv, DIR/table.md, DIR/scaling.csv and
// the log-log chart DIR/bench_scaling.png.
//
// Usage: bench_compare [--out DIR] [--quick | --smoke] [--only NAME,NAME...]
//   full:    the step counts below (about 6 minutes of CPU on a 2-core Xeon at 2.5 GHz)
//   --quick: a fifth of the steps
//   --smoke: tiny scenes and 10 steps, seconds: proves the command runs (a ctest), not timing
//   --only:  just the named scenes (the chart needs the scaling_* ones)
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/compare/compare_chart.h"
#include "bench/compare/compare_report.h"
#include "bench/compare/compare_run.h"
#include "bench/compare/compare_scene.h"

using namespace impulse2d::compare;

namespace {

enum class Size { Full, Quick, Smoke };

// The scenes and their full step counts: Box2D v3's own for its scenes (large_pyramid 500,
// many_pyramids 200), 600 for the small pyramid, 300 for the ball pit (5 s: the balls have
// landed), 600 for rain (10 s: the field is full and bodies recycle), 100 for each scaling
// point (the pyramids at rest, every step alike). About 6 minutes of CPU on the machine
// below; on a machine shared with other builds the wall-clock time is longer.
std::vector<CompareScene> scenes(Size size) {
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
  // Pyramids of 55 boxes: 18 -> 990, 36 -> 1980, 91 -> 5005, 182 -> 10010, 364 -> 20020.
  for (const int count : {18, 36, 91, 182, 364}) {
    list.push_back(many_pyramids_scene("scaling_" + std::to_string(count * 55), count, 20, 10,
                                       100 / divisor));
    list.back().scaling = true;
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

const char* const usage_line = "usage: bench_compare [--out DIR] [--quick | --smoke] [--only NAME,NAME...]";

int usage(const char* message) {
  std::fprintf(stderr, "bench_compare: %s\n%s\n", message, usage_line);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string directory = "out/bench_compare";
  Size size = Size::Full;
  std::string only;  // ",a,b," or empty for every scene
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) {
      directory = argv[++i];
    } else if (arg == "--only" && i + 1 < argc) {
      only = std::string(",") + argv[++i] + ",";
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
  try {
    std::filesystem::create_directories(directory);
    std::vector<std::string> notes;
    const std::vector<Contender> engines = contenders(notes);
    const int block = size == Size::Smoke ? 5 : 20;
    std::cout << "bench_compare: impulse2d against its peers, the same scenes in the same run\n"
              << "machine: " << cpu_model() << ", " << std::thread::hardware_concurrency()
              << " cores; one thread; steps of 1/60 s, sleeping off, gravity -10 m/s^2\n"
              << "ms/step: CPU time of each step, median; engines interleaved in blocks of "
              << block << " steps\n"
              << "stability: sag = largest drop of a pyramid's top box; side = largest sideways "
                 "move of a box; moved = boxes moved sideways > 0.1 m or turned > 5 degrees; "
                 "depth = deepest overlap of any two bodies (largest of 6 samples); out = balls "
                 "outside the pit at the end / recyc = rain bodies recycled\n";
    for (const std::string& note : notes) std::cout << "note: " << note << "\n";
    std::vector<SceneResult> results;
    std::vector<CompareScene> chosen;
    for (CompareScene& scene : scenes(size)) {
      if (only.empty() || only.find("," + scene.name + ",") != std::string::npos) chosen.push_back(std::move(scene));
    }
    if (chosen.empty()) {
      std::string names;
      for (const CompareScene& scene : scenes(size)) names += " " + scene.name;
      return usage(("--only names none of the scenes:" + names).c_str());
    }
    for (const CompareScene& scene : chosen) {
      const auto start = std::chrono::steady_clock::now();
      SceneResult result{scene.name, scene.description, scene.judge, scene.dynamic_count,
                         scene.steps, scene.scaling, {}, 0.0};
      result.outcomes = run_interleaved(scene, engines, scene.steps, block);
      result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      print_scene_table(std::cout, engines, result);
      std::cout.flush();
      results.push_back(result);
    }
    print_ratios(std::cout, engines, results);
    const std::filesystem::path out(directory);
    {
      std::ofstream csv(out / "results.csv", std::ios::binary | std::ios::trunc);
      write_csv(csv, engines, results);
      std::ofstream markdown(out / "table.md", std::ios::binary | std::ios::trunc);
      write_markdown(markdown, engines, results);
      if (!csv || !markdown) throw std::runtime_error("cannot write into " + directory);
    }
    std::string why;
    const std::string chart = write_scaling_chart(directory, engines, results, why);
    std::cout << "\nwrote " << (out / "results.csv").string() << ", " << (out / "table.md").string();
    if (!chart.empty()) std::cout << ", " << chart;
    std::cout << "\n";
    if (chart.empty()) std::cout << "no chart: " << why << "\n";
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_compare: %s\n", error.what());
    return 1;
  }
  return 0;
}

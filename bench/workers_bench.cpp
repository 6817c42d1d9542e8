// The multi-threaded step (issue 33): time per step at several worker counts
// (`WorldSettings::worker_count`) on Box2D v3's large pyramid (5050 boxes) and many pyramids
// (400 pyramids of 10 rows, 22 000 boxes), bench_compare's scenes at the default settings.
// Each worker count steps its own world of the scene, one after another in the same run, in
// `rounds` rounds (1, 2, 4, 1, 2, 4, ...: a machine whose load drifts slows every count alike);
// per count it prints the median over the rounds of
//   wall ms   - the median wall-clock time of a step
//   cpu ms    - the median CPU time of the calling thread in a step
//   all cpu   - the process's CPU time (every thread) per step, the mean over the steps
//   speed-up  - one worker's wall ms over this count's, in the same round
//   hash      - whether the state after the last step is bit-identical to one worker's
//               (exit status 1 when it is not, for any count)
// and the core count (std::thread::hardware_concurrency), the CPU and the load average before
// and after (the machine's other work slows every count). Usage:
//   bench_workers [--scene large_pyramid|many_pyramids|all] [--workers 1,2,4] [--steps N]
//                 [--rounds R]
// --steps overrides the scenes' own counts (large_pyramid 500, many_pyramids 200, Box2D v3's).
#include "bench/compare/compare_scene.h"
#include "core/world.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace impulse2d;

namespace {

struct Timing {
  double wall_ms = 0;        // median
  double thread_cpu_ms = 0;  // median, calling thread
  double process_cpu_ms = 0; // mean per step, every thread
  std::uint64_t hash = 0;
};

double cpu_ms(clockid_t clock) {
  timespec now{};
  clock_gettime(clock, &now);
  return 1000.0 * static_cast<double>(now.tv_sec) + 1.0e-6 * static_cast<double>(now.tv_nsec);
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<long>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

Timing run(const compare::CompareScene& scene, int workers, int steps) {
  WorldSettings settings;  // the default: soft step, 4 sub-steps
  settings.gravity = {0.0f, -10.0f};
  settings.worker_count = workers;
  World world(settings);
  for (const compare::BodySpec& spec : scene.bodies) world.create_body(spec.def, spec.shape);
  std::vector<double> wall, thread_cpu;
  wall.reserve(static_cast<std::size_t>(steps));
  thread_cpu.reserve(static_cast<std::size_t>(steps));
  const double process_start = cpu_ms(CLOCK_PROCESS_CPUTIME_ID);
  for (int s = 0; s < steps; ++s) {
    const auto wall_start = std::chrono::steady_clock::now();
    const double thread_start = cpu_ms(CLOCK_THREAD_CPUTIME_ID);
    world.step();
    thread_cpu.push_back(cpu_ms(CLOCK_THREAD_CPUTIME_ID) - thread_start);
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count());
  }
  Timing timing;
  timing.process_cpu_ms = (cpu_ms(CLOCK_PROCESS_CPUTIME_ID) - process_start) / steps;
  timing.wall_ms = median(wall);
  timing.thread_cpu_ms = median(thread_cpu);
  timing.hash = world.state_hash();
  return timing;
}

std::string first_line_with(const char* path, const char* key) {
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line)) {
    if (key == nullptr || line.rfind(key, 0) == 0) return line;
  }
  return "?";
}

std::string load_average() {
  std::istringstream fields(first_line_with("/proc/loadavg", nullptr));
  std::string one, five, fifteen;
  fields >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> worker_counts{1, 2, 4};
  std::string which = "all";
  int steps = 0;
  int rounds = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--workers" && i + 1 < argc) {
      worker_counts.clear();
      std::stringstream list(argv[++i]);
      std::string item;
      while (std::getline(list, item, ',')) {
        const int count = std::atoi(item.c_str());
        if (count < 1 || count > 64) {
          std::fprintf(stderr, "bench_workers: --workers: each count must be in 1..64 (got '%s')\n", item.c_str());
          return 2;
        }
        worker_counts.push_back(count);
      }
      if (worker_counts.empty() || worker_counts.front() != 1) worker_counts.insert(worker_counts.begin(), 1);
    } else if (arg == "--scene" && i + 1 < argc) {
      which = argv[++i];
      if (which != "large_pyramid" && which != "many_pyramids" && which != "all") {
        std::fprintf(stderr, "bench_workers: --scene must be large_pyramid, many_pyramids or all\n");
        return 2;
      }
    } else if (arg == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
      if (rounds < 1 || rounds > 100) {
        std::fprintf(stderr, "bench_workers: --rounds must be 1..100\n");
        return 2;
      }
    } else if (arg == "--steps" && i + 1 < argc) {
      steps = std::atoi(argv[++i]);
      if (steps < 1 || steps > 100000) {
        std::fprintf(stderr, "bench_workers: --steps must be 1..100000\n");
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: bench_workers [--scene large_pyramid|many_pyramids|all] [--workers 1,2,4] [--steps N] [--rounds R]\n");
      return 2;
    }
  }
  std::vector<compare::CompareScene> scenes;
  if (which != "many_pyramids") scenes.push_back(compare::pyramid_scene("large_pyramid", 100, 500));
  if (which != "large_pyramid") scenes.push_back(compare::many_pyramids_scene("many_pyramids", 400, 20, 10, 200));
  std::printf("cores: %u (std::thread::hardware_concurrency); %s\n", std::thread::hardware_concurrency(),
              first_line_with("/proc/cpuinfo", "model name").c_str());
  std::printf("load average before: %s\n", load_average().c_str());
  bool all_same = true;
  for (const compare::CompareScene& scene : scenes) {
    const int scene_steps = steps > 0 ? steps : scene.steps;
    std::printf("\n%s: %zu bodies, %d steps of 1/60 s, default settings (soft step), %d rounds\n",
                scene.name.c_str(), scene.bodies.size(), scene_steps, rounds);
    const std::size_t counts = worker_counts.size();
    std::vector<std::vector<double>> wall(counts), cpu(counts), all_cpu(counts), speed_up(counts);
    std::vector<bool> same(counts, true);
    for (int round = 0; round < rounds; ++round) {
      Timing single;
      for (std::size_t k = 0; k < counts; ++k) {
        const Timing t = run(scene, worker_counts[k], scene_steps);
        if (k == 0) single = t;
        wall[k].push_back(t.wall_ms);
        cpu[k].push_back(t.thread_cpu_ms);
        all_cpu[k].push_back(t.process_cpu_ms);
        speed_up[k].push_back(single.wall_ms / t.wall_ms);
        same[k] = same[k] && t.hash == single.hash;
      }
    }
    std::printf("%8s %9s %9s %9s %9s %s\n", "workers", "wall ms", "cpu ms", "all cpu", "speed-up", "hash = 1 worker's");
    for (std::size_t k = 0; k < counts; ++k) {
      std::printf("%8d %9.3f %9.3f %9.3f %9.2f %s\n", worker_counts[k], median(wall[k]), median(cpu[k]),
                  median(all_cpu[k]), median(speed_up[k]), same[k] ? "yes" : "NO");
      all_same = all_same && same[k];
    }
    std::fflush(stdout);
  }
  std::printf("\nload average after: %s\n", load_average().c_str());
  return all_same ? 0 : 1;
}

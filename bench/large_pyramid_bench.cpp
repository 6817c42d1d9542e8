// The large pyramid as Box2D v3's benchmark/large_pyramid builds it: a static ground box of
// half-size (100, 1) at (0, -1); `rows` rows of rotating boxes of half-size 0.5, touching, one
// metre apart, density 1, friction 0.6, gravity -10, 1/60 s, sleeping off. For each solver
// method: CPU time per step (median of the measured steps), its ratio to the default measured
// in the same run, and whether it stands by the criteria after `steps` steps:
//   sag     - how far the top box sits below where it was built (metres; at most 0.732, Box2D
//             v3's own sag on this scene measured on this machine: the "0.73 m")
//   side    - the largest sideways move of any box (metres; at most 0.1)
//   over    - how many boxes moved sideways more than 0.1 m
//   turn    - the largest turn of any box (degrees; at most 5)
// Box2D v3 is not in Debian; README "Measured figures: physics" quotes it built from source
// beside this program. Usage: bench_large_pyramid [--rows R] [--steps N] [--lanes 4|8] [--check]
// --check runs the soft step alone and exits 1 unless it stands (a ctest in optimised builds);
// --lanes picks the soft step's contact block width (default: the widest this CPU runs).
#include "core/solver/wide_contact_solver.h"
#include "core/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

struct Method {
  const char* name;
  WorldSettings settings;
};

std::vector<Method> methods(int lanes) {
  WorldSettings soft;  // the default: the soft step, 4 substeps of 1 soft and 1 relax pass
  soft.gravity = {0.0f, -10.0f};
  soft.solver_lanes = lanes;
  WorldSettings accumulated = settings_for(SolverMethod::Accumulated);
  accumulated.gravity = soft.gravity;
  return {{"accumulated, 16 iterations", accumulated},
          {"default: soft step, 4 substeps x 1 + 1 relax", soft}};
}

struct Outcome {
  double ms_per_step = 0;
  float sag = 0, side = 0, turn_degrees = 0;
  int over = 0;
};

Outcome run(const WorldSettings& settings, int rows, int steps) {
  World world(settings);
  const Material ground_material{"Ground", 0.0f, 0.0f, 0.6f, 0.6f};
  const Material box_material{"Box", 1.0f, 0.0f, 0.6f, 0.6f};
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = ground_material;
  ground.position = {0.0f, -1.0f};
  world.create_body(ground, make_oriented_box({100.0f, 1.0f}));
  std::vector<BodyId> boxes;
  std::vector<vec2> built;
  const float a = 0.5f;
  for (int i = 0; i < rows; ++i) {
    for (int j = i; j < rows; ++j) {
      BodyDef def;
      def.material = box_material;
      def.position = {(static_cast<float>(i) + 1.0f) * a + 2.0f * static_cast<float>(j - i) * a -
                          a * static_cast<float>(rows),
                      (2.0f * static_cast<float>(i) + 1.0f) * a};
      boxes.push_back(world.create_body(def, make_oriented_box({a, a})));
      built.push_back(def.position);
    }
  }
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(steps));
  for (int s = 0; s < steps; ++s) {
    const std::clock_t start = std::clock();
    world.step();
    times.push_back(1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC);
  }
  Outcome outcome;
  std::nth_element(times.begin(), times.begin() + static_cast<long>(times.size() / 2), times.end());
  outcome.ms_per_step = times[times.size() / 2];
  outcome.sag = built.back().y - world.body(boxes.back()).transform.position.y;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const BodyView body = world.body(boxes[i]);
    const float side = std::fabs(body.transform.position.x - built[i].x);
    outcome.side = std::max(outcome.side, side);
    if (side > 0.1f) ++outcome.over;
    outcome.turn_degrees = std::max(outcome.turn_degrees, std::fabs(body.angle) * 57.29578f);
  }
  return outcome;
}

}  // namespace

int main(int argc, char** argv) {
  int rows = 100, steps = 500, lanes = 0;
  bool check = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--check") {
      check = true;
    } else if ((arg == "--rows" || arg == "--steps") && i + 1 < argc) {
      const int value = std::atoi(argv[++i]);
      if (value < 1 || value > 1000) {
        std::fprintf(stderr, "bench_large_pyramid: %s must be 1..1000\n", arg.c_str());
        return 2;
      }
      (arg == "--rows" ? rows : steps) = value;
    } else if (arg == "--lanes" && i + 1 < argc) {
      lanes = std::atoi(argv[++i]);
      if (lanes != 4 && lanes != 8) {
        std::fprintf(stderr, "bench_large_pyramid: --lanes must be 4 or 8\n");
        return 2;
      }
      if (lanes > WideContactSolver::widest_lanes()) {
        std::fprintf(stderr, "bench_large_pyramid: this CPU runs at most %d lanes\n",
                     WideContactSolver::widest_lanes());
        return 2;
      }
    } else {
      std::fprintf(stderr, "usage: bench_large_pyramid [--rows R] [--steps N] [--lanes 4|8] [--check]\n");
      return 2;
    }
  }
  std::printf("large pyramid: %d rows (%d boxes), %d steps of 1/60 s, CPU time\n", rows,
              rows * (rows + 1) / 2, steps);
  std::printf("%-38s %8s %6s %7s %7s %6s %7s %s\n", "method", "ms/step", "ratio", "sag m", "side m",
              "over", "turn °", "stands (sag <= 0.732, side <= 0.1, turn <= 5)");
  double baseline = 0;
  bool all_stand = true;
  for (const Method& method : methods(lanes)) {
    if (check && method.settings.solver != SolverMethod::SoftStep) continue;
    const Outcome o = run(method.settings, rows, steps);
    if (baseline == 0) baseline = o.ms_per_step;
    const bool stands = o.sag <= 0.732f && o.side <= 0.1f && o.turn_degrees <= 5.0f;
    all_stand = all_stand && stands;
    std::printf("%-38s %8.3f %6.2f %7.3f %7.3f %6d %7.2f %s\n", method.name, o.ms_per_step,
                o.ms_per_step / baseline, o.sag, o.side, o.over, o.turn_degrees, stands ? "yes" : "no");
  }
  return check && !all_stand ? 1 : 0;
}

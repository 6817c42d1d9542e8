// Speed against accuracy for every solver method on the 20-row pyramid (210 boxes).
//
// For each method: median wall-clock time per step over the measured steps, its ratio to the
// tutorial's per-iteration solver measured in the same run (these machines are shared and
// noisy, so only ratios within one run mean something), and accuracy figures:
//   sink   - how far the top box sits below its exact resting height (metres)
//   drift  - how far the top box moved during the last 4 s (metres; 0 for a perfect solver)
//   moved  - boxes out of place: moved sideways more than the slop, or sunk more than the
//            slop each contact below them may keep (row + 1) * slop
//   depth  - deepest overlap left at the end (metres)
//   error  - the worst box's distance out of place (sideways, or sunk beyond the slop its
//            contacts may keep), metres: the accuracy axis of the speed/accuracy chart
// With --sweep it instead runs the solver families over iteration (and substep) budgets and
// writes one CSV row per run (family,iterations,substeps,ms_per_step,error_m; family is
// tutorial, cold, warm, substeps or soft_step)
// for bench/chart_solver.sh to plot.
// Usage: bench_solver [--steps N] [--rows R] [--csv FILE] [--sweep]
#include "core/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

struct Method {
  std::string name;
  WorldSettings settings;
};

std::vector<Method> methods() {
  std::vector<Method> list;
  WorldSettings tutorial = settings_for(SolverMethod::PerIteration);
  tutorial.position_correction = PositionCorrection::LinearProjection;
  tutorial.correction_percent = 0.4f;
  tutorial.slop = 0.05f;
  tutorial.friction_mixing = FrictionMixing::RootSumSquares;
  tutorial.restitution_mixing = RestitutionMixing::Minimum;
  list.push_back({"tutorial per-iteration + linear projection", tutorial});

  WorldSettings cold = settings_for(SolverMethod::Accumulated);
  cold.warm_starting = false;
  cold.block_solver = false;
  cold.position_correction = PositionCorrection::LinearProjection;
  list.push_back({"accumulated, no warm start + linear", cold});

  WorldSettings warm = cold;
  warm.warm_starting = true;
  list.push_back({"accumulated + warm start + linear", warm});

  WorldSettings ngs = warm;
  ngs.position_correction = PositionCorrection::NonlinearGaussSeidel;
  list.push_back({"accumulated + warm start + NGS", ngs});

  WorldSettings block = ngs;
  block.block_solver = true;
  list.push_back({"accumulated + warm + block + NGS", block});

  WorldSettings eight = block;
  eight.velocity_iterations = 8;
  list.push_back({"accumulated with 8 iterations", eight});

  WorldSettings no_speculation = block;
  no_speculation.speculative_margin = 0.0f;
  list.push_back({"accumulated without speculative contacts", no_speculation});

  WorldSettings brute = block;
  brute.broad_phase = BroadPhaseMethod::BruteForce;
  list.push_back({"accumulated with brute-force broad phase", brute});

  WorldSettings substeps = block;
  substeps.substeps = 4;
  substeps.velocity_iterations = 2;
  list.push_back({"accumulated, 4 substeps x 2 iterations", substeps});

  // The default: Box2D v3's soft step, 4 sub-steps of one soft pass and one relax pass.
  list.push_back({"default: soft step, 4 substeps x 1 + 1 relax", WorldSettings{}});
  return list;
}

struct Result {
  double median_ms = 0;
  double sink = 0, drift = 0, depth = 0, error = 0;
  int moved = 0;
};

Result run(const WorldSettings& settings, int rows, int steps) {
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -0.5f};
  world.create_body(ground, make_box({rows * 1.0f + 10, 0.5f}));
  std::vector<BodyId> boxes;
  std::vector<vec2> exact;
  std::vector<int> row_of;
  const Shape box = make_oriented_box({0.5f, 0.5f});
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i < rows - row; ++i) {
      BodyDef def;
      def.material = materials::wood();
      def.position = {(static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1)) * 1.05f,
                      0.5f + static_cast<float>(row)};
      boxes.push_back(world.create_body(def, box));
      exact.push_back(def.position);
      row_of.push_back(row);
    }
  }
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(steps));
  const int drift_from = steps - 240;
  vec2 top_at_drift_start{0};
  for (int s = 0; s < steps; ++s) {
    if (s == drift_from) top_at_drift_start = world.body(boxes.back()).transform.position;
    const auto start = std::chrono::steady_clock::now();
    world.step();
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  Result result;
  std::nth_element(times.begin(), times.begin() + static_cast<long>(times.size() / 2), times.end());
  result.median_ms = times[times.size() / 2];
  const vec2 top = world.body(boxes.back()).transform.position;
  result.sink = exact.back().y - top.y;
  result.drift = glm::length(top - top_at_drift_start);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const vec2 offset = world.body(boxes[i]).transform.position - exact[i];
    const float allowed_sink = static_cast<float>(row_of[i] + 1) * settings.slop;
    if (std::fabs(offset.x) > settings.slop || -offset.y > allowed_sink + settings.slop) ++result.moved;
    result.error = std::max({result.error, double(std::fabs(offset.x)), double(-offset.y - allowed_sink)});
  }
  for (const Contact& contact : world.contacts()) {
    for (int i = 0; i < contact.point_count; ++i) result.depth = std::max(result.depth, double(contact.points[i].depth));
  }
  return result;
}

// Solver families over iteration budgets: the data of the speed/accuracy chart.
void sweep(int rows, int steps, const std::string& csv_path) {
  std::ofstream csv(csv_path);
  csv << "family,iterations,substeps,ms_per_step,error_m\n";
  const std::vector<Method> all = methods();
  const std::pair<const char*, Method> families[] = {{"tutorial", all[0]}, {"cold", all[1]}, {"warm", all[4]}};
  for (const auto& [key, family] : families) {
    for (int iterations : {1, 2, 4, 8, 16, 32}) {
      WorldSettings settings = family.settings;
      settings.velocity_iterations = iterations;
      const Result r = run(settings, rows, steps);
      csv << key << ',' << iterations << ",1," << r.median_ms << ',' << r.error << '\n';
      std::printf("%-44s iterations %2d: %7.3f ms/step, error %.4f m\n", family.name.c_str(), iterations,
                  r.median_ms, r.error);
    }
  }
  for (int substeps : {1, 2, 4, 8}) {
    WorldSettings settings = all[4].settings;
    settings.velocity_iterations = 1;
    settings.substeps = substeps;
    const Result r = run(settings, rows, steps);
    csv << "substeps,1," << substeps << ',' << r.median_ms << ',' << r.error << '\n';
    std::printf("%-44s substeps %2d: %7.3f ms/step, error %.4f m\n", "accumulated, substeps x 1 iteration", substeps,
                r.median_ms, r.error);
  }
  for (int substeps : {1, 2, 4, 8}) {
    WorldSettings settings = all.back().settings;  // the soft step
    settings.substeps = substeps;
    const Result r = run(settings, rows, steps);
    csv << "soft_step,1," << substeps << ',' << r.median_ms << ',' << r.error << '\n';
    std::printf("%-44s substeps %2d: %7.3f ms/step, error %.4f m\n", "soft step, substeps x 1 + 1 relax", substeps,
                r.median_ms, r.error);
  }
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 600, rows = 20;
  std::string csv_path;
  bool sweep_budgets = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--sweep") {
      sweep_budgets = true;
    } else if ((arg == "--steps" || arg == "--rows" || arg == "--csv") && i + 1 < argc) {
      const std::string value = argv[++i];
      if (arg == "--csv") {
        csv_path = value;
      } else {
        const int number = std::atoi(value.c_str());
        if (number < (arg == "--steps" ? 300 : 1)) {
          std::fprintf(stderr, "bench_solver: %s must be %s\n", arg.c_str(),
                       arg == "--steps" ? ">= 300" : ">= 1");
          return 2;
        }
        (arg == "--steps" ? steps : rows) = number;
      }
    } else {
      std::fprintf(stderr, "usage: bench_solver [--steps N>=300] [--rows R] [--csv FILE] [--sweep]\n");
      return 2;
    }
  }
  if (sweep_budgets) {
    if (csv_path.empty()) {
      std::fprintf(stderr, "bench_solver: --sweep needs --csv FILE\n");
      return 2;
    }
    sweep(rows, steps, csv_path);
    return 0;
  }
  std::printf("pyramid of %d rows (%d boxes), %d steps of 1/60 s, %d velocity iterations unless named\n",
              rows, rows * (rows + 1) / 2, steps, WorldSettings{}.velocity_iterations);
  std::printf("%-44s %9s %7s %8s %8s %6s %8s %8s\n", "method", "ms/step", "ratio", "sink m", "drift m", "moved",
              "depth m", "error m");
  std::ofstream csv;
  if (!csv_path.empty()) {
    csv.open(csv_path);
    csv << "method,ms_per_step,ratio,sink_m,drift_m,moved,depth_m,error_m\n";
  }
  double baseline = 0;
  for (const Method& method : methods()) {
    const Result r = run(method.settings, rows, steps);
    if (baseline == 0) baseline = r.median_ms;
    std::printf("%-44s %9.3f %7.2f %8.4f %8.4f %6d %8.4f %8.4f\n", method.name.c_str(), r.median_ms,
                r.median_ms / baseline, r.sink, r.drift, r.moved, r.depth, r.error);
    if (csv) {
      csv << '"' << method.name << "\"," << r.median_ms << ',' << r.median_ms / baseline << ',' << r.sink << ','
          << r.drift << ',' << r.moved << ',' << r.depth << ',' << r.error << '\n';
    }
  }
  return 0;
}

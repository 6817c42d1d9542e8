/// @file lab_tune.cpp
#include "lab/lab_tune.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "lab/engine_simulation.h"
#include "lab/json_number.h"

namespace impulse2d::lab {
namespace {

/// Positions of every living body at each sample time, by world slot (bodies spawned or removed
/// by a scene's script or events are compared slot by slot; a slot empty in either run is
/// skipped).
struct Trajectory {
  std::vector<std::vector<std::optional<vec2>>> samples;
  bool diverged = false;
};

/// Seconds between samples: a whole number of the coarsest candidate step (2 dt), about 0.1 s.
double sample_interval(const demos::Scene& scene) {
  const double coarsest = 2.0 * scene.settings.time_step;
  return coarsest * std::max(1.0, std::ceil(0.1 / coarsest - 1e-9));
}

Trajectory record(const demos::Scene& scene, const demos::Params& params, const LabMethod& method,
                  double duration) {
  EngineSimulation simulation(scene, method, params);
  const double interval = sample_interval(scene);
  const long steps_per_sample = std::lround(interval / method.time_step);
  const long sample_count = std::max(1L, static_cast<long>(std::floor(duration / interval + 1e-9)));
  Trajectory trajectory;
  for (long sample = 0; sample < sample_count; ++sample) {
    for (long step = 0; step < steps_per_sample; ++step) simulation.step();
    const World& world = simulation.world();
    std::vector<std::optional<vec2>> positions;
    for (const BodyId id : world.body_ids()) {
      if (positions.size() <= id.index) positions.resize(id.index + 1);
      positions[id.index] = world.body(id).transform.position;
    }
    trajectory.samples.push_back(positions);
  }
  trajectory.diverged = simulation.diverged();
  return trajectory;
}

double compare(const Trajectory& run, const Trajectory& reference, TuneMetric metric) {
  if (run.diverged) return std::numeric_limits<double>::infinity();
  double worst = 0.0;
  const std::size_t first = metric == TuneMetric::Final ? run.samples.size() - 1 : 0;
  for (std::size_t sample = first; sample < run.samples.size(); ++sample) {
    const std::vector<std::optional<vec2>>& a = run.samples[sample];
    const std::vector<std::optional<vec2>>& b = reference.samples[sample];
    for (std::size_t slot = 0; slot < std::min(a.size(), b.size()); ++slot) {
      if (!a[slot] || !b[slot]) continue;
      const double distance = std::hypot(a[slot]->x - b[slot]->x, a[slot]->y - b[slot]->y);
      if (!std::isfinite(distance)) return std::numeric_limits<double>::infinity();
      worst = std::max(worst, distance);
    }
  }
  return worst;
}

/// Median wall-clock microseconds per simulated second of each method, repeats interleaved.
/// `after_run` is called after each run.
std::vector<double> time_methods(const demos::Scene& scene, const demos::Params& params,
                                 const std::vector<LabMethod>& methods, double duration,
                                 int repeats, const std::function<void()>& after_run) {
  std::vector<std::vector<double>> samples(methods.size());
  for (int repeat = 0; repeat < repeats; ++repeat) {
    for (std::size_t i = 0; i < methods.size(); ++i) {
      EngineSimulation simulation(scene, methods[i], params);
      const long steps = std::lround(duration / methods[i].time_step);
      const auto start = std::chrono::steady_clock::now();
      for (long step = 0; step < steps; ++step) simulation.step();
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      samples[i].push_back(seconds * 1e6 / duration);
      after_run();
    }
  }
  std::vector<double> medians;
  for (std::vector<double>& values : samples) {
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    medians.push_back(values.size() % 2 ? values[middle]
                                        : 0.5 * (values[middle - 1] + values[middle]));
  }
  return medians;
}


}  // namespace

LabMethod tune_reference(const demos::Scene& scene) {
  LabMethod reference = scene_method(scene);
  reference.time_step = scene.settings.time_step / 4.0f;
  reference.substeps = 4;
  reference.velocity_iterations = 32;
  reference.position_iterations = std::max(reference.position_iterations, 8);
  return reference;
}

std::vector<LabMethod> tune_candidates(const demos::Scene& scene, bool quick) {
  const LabMethod own = scene_method(scene);
  const bool fixed_step = !scene.events.empty() || static_cast<bool>(scene.script);
  std::vector<LabMethod> candidates;
  const std::vector<int> iterations = quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 4, 8, 16};
  const std::vector<int> substeps = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4};
  for (const SolverMethod solver :
       {SolverMethod::Accumulated, SolverMethod::SoftStep, SolverMethod::PerIteration}) {
    if (quick && solver == SolverMethod::PerIteration) continue;
    for (const int steps : substeps) {
      for (const int count : iterations) {
        LabMethod method = own;
        method.solver = solver;
        method.substeps = steps;
        method.velocity_iterations = count;
        if (solver == SolverMethod::Accumulated) {
          method.warm_starting = true;
          method.block_solver = true;
          method.shock_propagation = true;
        }
        candidates.push_back(method);
      }
    }
  }
  const int accumulated_substeps = settings_for(SolverMethod::Accumulated).substeps;
  for (const int count : {2, 4, 8}) {
    for (const PositionCorrection correction :
         {PositionCorrection::None, PositionCorrection::LinearProjection,
          PositionCorrection::NonlinearGaussSeidel}) {
      // Position correction serves accumulated impulses at one step a frame (settings_for's
      // sub-steps; the soft step ignores it).
      LabMethod method = own;
      method.solver = SolverMethod::Accumulated;
      method.substeps = accumulated_substeps;
      method.velocity_iterations = count;
      method.position_correction = correction;
      if (correction != own.position_correction) candidates.push_back(method);
    }
    if (!fixed_step) {
      for (const float factor : {2.0f, 0.5f}) {
        LabMethod method = own;
        method.solver = SolverMethod::Accumulated;
        method.substeps = accumulated_substeps;
        method.velocity_iterations = count;
        method.time_step = own.time_step * factor;
        candidates.push_back(method);
      }
    }
  }
  return candidates;
}

double tune_error(const demos::Scene& scene, const demos::Params& params, const LabMethod& method,
                  const LabMethod& reference, TuneMetric metric, double duration) {
  return compare(record(scene, params, method, duration),
                 record(scene, params, reference, duration), metric);
}

std::int64_t tune_runs(std::size_t candidates, int repeats) {
  const auto methods = static_cast<std::int64_t>(candidates) + 2;
  return methods + methods * repeats;
}

TuneResult tune_scene(const demos::Scene& scene, const demos::Params& params,
                      const TuneOptions& options) {
  const std::vector<LabMethod> candidates = tune_candidates(scene, options.quick);
  std::int64_t done = 0;
  std::int64_t total = tune_runs(candidates.size(), options.repeats);
  const auto after_run = [&]() {
    if (options.progress) options.progress(++done, total);
  };
  TuneResult result;
  result.reference.method = tune_reference(scene);
  result.scene_default.method = scene_method(scene);
  const Trajectory reference = record(scene, params, result.reference.method, options.duration);
  after_run();
  result.scene_default.error =
      compare(record(scene, params, result.scene_default.method, options.duration), reference,
              options.metric);
  after_run();
  std::vector<LabMethod> timed{result.reference.method, result.scene_default.method};
  std::vector<std::size_t> timed_candidates;
  for (const LabMethod& method : candidates) {
    TuneCandidate candidate;
    candidate.method = method;
    candidate.error = compare(record(scene, params, method, options.duration), reference,
                              options.metric);
    after_run();
    if (candidate.error <= options.max_error) {
      timed_candidates.push_back(result.candidates.size());
      timed.push_back(method);
    }
    result.candidates.push_back(candidate);
  }
  total = done + static_cast<std::int64_t>(timed.size()) * options.repeats;
  const std::vector<double> costs =
      time_methods(scene, params, timed, options.duration, options.repeats, after_run);
  result.reference.us_per_simulated_second = costs[0];
  result.scene_default.us_per_simulated_second = costs[1];
  for (std::size_t i = 0; i < timed_candidates.size(); ++i) {
    TuneCandidate& candidate = result.candidates[timed_candidates[i]];
    candidate.us_per_simulated_second = costs[i + 2];
    if (!result.found || candidate.us_per_simulated_second < result.chosen.us_per_simulated_second) {
      result.chosen = candidate;
      result.found = true;
    }
  }
  return result;
}

nlohmann::ordered_json tuned_settings(const LabMethod& method, const demos::SceneModel& model) {
  nlohmann::ordered_json settings;
  settings["solver"] = solver_name(method.solver);
  settings["time_step"] = json_number(method.time_step, "settings.time_step");
  settings["substeps"] = method.substeps;
  settings["position_correction"] = correction_name(method.position_correction);
  settings["speculative_margin"] = json_number(method.speculative_margin, "settings.speculative_margin");
  settings["integrator"] = integrator_name(method.integrator);
  settings["warm_starting"] = method.warm_starting;
  settings["block_solver"] = method.block_solver;
  settings["shock_propagation"] = method.shock_propagation;
  settings["friction_mixing"] = friction_mixing_name(method.friction_mixing);
  settings["restitution_mixing"] = restitution_mixing_name(method.restitution_mixing);
  nlohmann::ordered_json shapes = nlohmann::ordered_json::array();
  if (model.circles) shapes.push_back("circle");
  if (model.boxes) shapes.push_back("box");
  if (model.polygons) shapes.push_back("polygon");
  if (model.capsules) shapes.push_back("capsule");
  if (model.segments) shapes.push_back("segment");
  nlohmann::ordered_json switches;
  switches["shapes"] = shapes;
  switches["rotation"] = model.rotation;
  switches["friction"] = model.friction;
  switches["restitution"] = model.restitution;
  switches["ccd"] = model.ccd;
  switches["sleeping"] = model.sleeping;
  switches["velocity_iterations"] = method.velocity_iterations;
  switches["position_iterations"] = method.position_iterations;
  nlohmann::ordered_json answer;
  answer["settings"] = settings;
  answer["model"] = switches;
  return answer;
}

}  // namespace impulse2d::lab

/// @file lab_sweep.cpp
#include "lab/lab_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

#include "lab/instruction_counter.h"
#include "lab/lab_peers.h"
#include "scene/interrupt.h"

namespace impulse2d::lab {
namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

std::string describe_number(double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

/// One configuration of the sweep and what its repeats measured.
struct Job {
  std::int64_t index = 0;
  const LabScenario* scenario = nullptr;
  LabMethod method;
  std::vector<double> ns_per_step;
  std::vector<double> instructions_per_step;
  RunMeasurement first;
  bool nondeterministic = false;
  std::string exception;
};

}  // namespace

RunMeasurement run_scenario(const LabScenario& scenario, LabSimulation& simulation, bool observe,
                            bool count_instructions) {
  RunMeasurement measurement;
  measurement.bodies = simulation.body_count();
  const double time_step = simulation.time_step();
  measurement.steps = static_cast<std::int64_t>(std::ceil(scenario.duration / time_step - 1e-6));
  if (observe) {
    std::unique_ptr<MetricTracker> tracker = make_metric_tracker(scenario.metric, simulation);
    std::vector<BodyState> states;
    Clock::duration stepping{};
    for (std::int64_t step = 1; step <= measurement.steps; ++step) {
      const Clock::time_point start = Clock::now();
      simulation.step();
      stepping += Clock::now() - start;
      simulation.read_states(states);
      tracker->observe(static_cast<double>(step) * time_step, states);
    }
    measurement.step_seconds = std::chrono::duration<double>(stepping).count();
    measurement.error = tracker->error();
  } else {
    static thread_local InstructionCounter counter;
    const bool counting = count_instructions && counter.available();
    if (counting) counter.start();
    const Clock::time_point start = Clock::now();
    for (std::int64_t step = 1; step <= measurement.steps; ++step) simulation.step();
    measurement.step_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (counting) measurement.instructions = counter.stop();
  }
  measurement.diverged = simulation.diverged();
  measurement.hash = simulation.state_hash();
  return measurement;
}

std::vector<LabMethod> sweep_methods(const LabScenario& scenario, bool quick, bool peers) {
  std::vector<LabMethod> methods = method_space(quick);
  if (peers) {
    for (const LabMethod& peer : peer_methods(scenario.scene.settings.time_step)) {
      if (engine_available(peer.engine)) methods.push_back(peer);
    }
  }
  return methods;
}

std::vector<LabResult> run_sweep(const std::vector<LabScenario>& scenarios,
                                 const SweepOptions& options) {
  std::vector<Job> jobs;
  std::int64_t index = 0;
  for (const LabScenario& scenario : scenarios) {
    for (const LabMethod& method : sweep_methods(scenario, options.quick, options.peers)) {
      if (index % options.shard_count == options.shard_index) {
        Job job;
        job.index = index;
        job.scenario = &scenario;
        job.method = method;
        jobs.push_back(job);
      }
      ++index;
    }
  }

  const std::int64_t total = static_cast<std::int64_t>(jobs.size()) * options.repeats;
  std::int64_t done = 0;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    for (Job& job : jobs) {
      demos::check_interrupt();
      if (!job.exception.empty()) {
        ++done;
        continue;
      }
      try {
        std::unique_ptr<LabSimulation> simulation = make_simulation(job.scenario->scene, job.method);
        const RunMeasurement run =
            run_scenario(*job.scenario, *simulation, repeat == 0, options.count_instructions);
        const double steps = static_cast<double>(std::max<std::int64_t>(run.steps, 1));
        job.ns_per_step.push_back(run.step_seconds * 1e9 / steps);
        if (run.instructions > 0) job.instructions_per_step.push_back(run.instructions / steps);
        if (repeat == 0) job.first = run;
        else if (run.hash != job.first.hash) job.nondeterministic = true;
      } catch (const demos::Interrupted&) {
        throw;  // a signal stops the sweep, it does not fail a run
      } catch (const std::exception& error) {
        job.exception = error.what();
      }
      if (options.progress) options.progress(++done, total);
    }
  }

  std::vector<LabResult> results;
  for (const Job& job : jobs) {
    LabResult result;
    result.job = job.index;
    result.scenario = job.scenario->name;
    result.method = job.method;
    result.unit = job.scenario->metric.unit;
    result.threshold = job.scenario->metric.threshold;
    result.steps = job.first.steps;
    result.bodies = job.first.bodies;
    result.repeats = static_cast<int>(job.ns_per_step.size());
    result.ns_per_step = median(job.ns_per_step);
    result.ns_per_step_body = result.bodies > 0 ? result.ns_per_step / result.bodies : 0.0;
    result.us_per_simulated_second = result.ns_per_step / job.method.time_step / 1000.0;
    result.instructions_per_step = median(job.instructions_per_step);
    result.error = job.exception.empty() ? job.first.error : std::numeric_limits<double>::infinity();
    if (!job.exception.empty()) {
      result.failure = "run failed: " + job.exception;
    } else if (job.first.diverged || !std::isfinite(result.error)) {
      result.failure = "diverged: bodies went non-finite";
      result.error = std::numeric_limits<double>::infinity();
    } else if (job.nondeterministic) {
      result.failure = "nondeterministic: repeats ended in different states";
    } else if (result.error > result.threshold) {
      result.failure = "error " + describe_number(result.error) + " " + result.unit + " > " +
                       describe_number(result.threshold) + " " + result.unit;
    }
    result.pass = result.failure.empty();
    results.push_back(result);
  }
  mark_fronts(results);
  return results;
}

}  // namespace impulse2d::lab

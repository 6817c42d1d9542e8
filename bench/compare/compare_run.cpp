/// @file compare_run.cpp
#include "bench/compare/compare_run.h"

#include <malloc.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>

#include "bench/compare/world_simulation.h"
#include "lab/lab_peers.h"
#include "core/world.h"
#include "scene/scene.h"
#include "scene/scene_model.h"

namespace impulse2d::compare {
namespace {

// The scene as a demos::Scene, so the lab makes its peers from it (`lab::make_simulation`).
demos::Scene lab_scene(const CompareScene& scene) {
  demos::Scene result;
  result.name = scene.name;
  result.description = scene.description;
  result.settings.gravity = {0.0f, -10.0f};
  result.model.circles = true;
  result.model.polygons = true;
  result.build = [&scene](World& world, const demos::Params&) {
    for (const BodySpec& spec : scene.bodies) world.create_body(spec.def, spec.shape);
  };
  return result;
}

// impulse2d's settings for `method` as the lab applies them to a scene.
WorldSettings settings_for(const demos::Scene& scene, const lab::LabMethod& method) {
  const demos::Scene applied = lab::apply_method(method, scene);
  WorldSettings settings = applied.settings;
  demos::apply_model(applied.model, settings);
  return settings;
}

std::unique_ptr<lab::LabSimulation> make_run(const CompareScene& scene, const lab::LabMethod& method) {
  const demos::Scene wrapped = lab_scene(scene);
  if (method.engine == lab::Engine::Impulse2d) {
    return std::make_unique<WorldSimulation>(scene, settings_for(wrapped, method));
  }
  return lab::make_simulation(wrapped, method);
}

double thread_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

// Rain's places above the field for one engine: the step each was last used in.
struct RecycleState {
  std::vector<long> last_used;  // per place; far in the past at first
  int next = 0;                 // the place tried first
};

// Rain: every dynamic body below the field (or no longer finite) goes back above it, to the
// next place that has been free for `spacing_steps`; with none free it waits a step.
void recycle(const CompareScene& scene, lab::LabSimulation& run, long step,
             std::vector<lab::BodyState>& states, RecycleState& places, int& recycled) {
  const Recycle& rule = scene.recycle;
  if (places.last_used.empty()) places.last_used.assign(static_cast<std::size_t>(rule.slots), -rule.spacing_steps);
  run.read_states(states);
  for (std::size_t i = 0; i < states.size(); ++i) {
    const lab::BodyState& state = states[i];
    if (!state.dynamic || (std::isfinite(state.position.y) && state.position.y >= rule.below)) continue;
    int place = -1;
    for (int tried = 0; tried < rule.slots && place < 0; ++tried) {
      const int candidate = (places.next + tried) % rule.slots;
      if (step - places.last_used[static_cast<std::size_t>(candidate)] >= rule.spacing_steps) place = candidate;
    }
    if (place < 0) return;
    places.last_used[static_cast<std::size_t>(place)] = step;
    places.next = (place + 1) % rule.slots;
    const float fraction = rule.slots > 1 ? static_cast<float>(place) / static_cast<float>(rule.slots - 1) : 0.0f;
    run.place_body(static_cast<int>(i), {rule.left + fraction * (rule.right - rule.left), rule.top},
                   {0.0f, -rule.speed});
    ++recycled;
  }
}

// Bytes malloc has handed out and not taken back: in the arenas plus mmapped blocks.
double heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks) + static_cast<double>(info.hblkhd);
}

// The process's resident set, bytes (the second field of /proc/self/statm, in pages); -1 when
// it cannot be read.
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long total_pages = 0;
  long resident_pages = 0;
  if (!(statm >> total_pages >> resident_pages)) return -1.0;
  return static_cast<double>(resident_pages) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

WorldSettings impulse2d_settings(const CompareScene& scene, const lab::LabMethod& method) {
  return settings_for(lab_scene(scene), method);
}

std::vector<Contender> contenders(std::vector<std::string>& notes) {
  // The default (the soft step, 4 sub-steps x 1 pass) and the accumulated solver at the
  // sub-steps and passes it is measured at (settings_for).
  const WorldSettings accumulated_settings = impulse2d::settings_for(SolverMethod::Accumulated);
  lab::LabMethod accumulated;
  accumulated.solver = accumulated_settings.solver;
  accumulated.substeps = accumulated_settings.substeps;
  accumulated.velocity_iterations = accumulated_settings.velocity_iterations;
  std::vector<Contender> result;
  for (const lab::LabMethod& method : {lab::LabMethod{}, accumulated}) {
    result.push_back({"impulse2d " + lab::method_label(method), method});
  }
  for (const lab::LabMethod& method : lab::peer_methods(WorldSettings{}.time_step)) {
    const std::string note = lab::engine_note(method.engine);
    if (!note.empty()) notes.push_back(note);
    if (lab::engine_available(method.engine)) result.push_back({lab::method_label(method), method});
  }
  return result;
}

std::vector<Outcome> run_interleaved(const CompareScene& scene,
                                     const std::vector<Contender>& contenders,
                                     const std::vector<bool>& included, int steps, int block) {
  const std::size_t count = contenders.size();
  std::vector<std::unique_ptr<lab::LabSimulation>> runs;
  for (std::size_t e = 0; e < count; ++e) {
    runs.push_back(included[e] ? make_run(scene, contenders[e].method) : nullptr);
  }
  std::vector<std::vector<double>> times(count);
  for (std::vector<double>& list : times) list.reserve(static_cast<std::size_t>(steps));
  std::vector<Outcome> outcomes(count);
  std::vector<lab::BodyState> states;
  std::vector<RecycleState> places(count);
  const int blocks = (steps + block - 1) / block;
  const int sample_every = std::max(1, blocks / 5);
  for (int b = 0; b < blocks; ++b) {
    const int block_steps = std::min(block, steps - b * block);
    const bool sample = (b + 1) % sample_every == 0 || b + 1 == blocks;
    for (std::size_t e = 0; e < count; ++e) {
      if (!runs[e]) continue;
      lab::LabSimulation& run = *runs[e];
      for (int s = 0; s < block_steps; ++s) {
        const double start = thread_cpu_ms();
        run.step();
        times[e].push_back(thread_cpu_ms() - start);
        if (scene.judge == Judge::Rain) {
          recycle(scene, run, static_cast<long>(b) * block + s, states, places[e], outcomes[e].stability.out);
        }
      }
      if (sample) {
        run.read_states(states);
        Stability& stability = outcomes[e].stability;
        stability.depth = std::max(stability.depth, deepest_overlap(scene, states));
      }
    }
  }
  for (std::size_t e = 0; e < count; ++e) {
    if (!runs[e]) {
      outcomes[e].ran = false;
      continue;
    }
    outcomes[e].ms_per_step = median(times[e]);
    runs[e]->read_states(states);
    judge_final_states(scene, states, outcomes[e].stability);
  }
  return outcomes;
}

MemoryUse measure_memory(const CompareScene& scene, const Contender& contender, int steps) {
  malloc_trim(0);
  const double heap_before = heap_in_use();
  const double resident_before = resident_bytes();
  MemoryUse use;
  {
    std::unique_ptr<lab::LabSimulation> run = make_run(scene, contender.method);
    for (int s = 0; s < steps; ++s) run->step();
    use.heap_bytes = heap_in_use() - heap_before;
    malloc_trim(0);
    const double resident_after = resident_bytes();
    if (resident_before >= 0.0 && resident_after >= 0.0) use.resident_bytes = resident_after - resident_before;
  }
  malloc_trim(0);
  return use;
}

}  // namespace impulse2d::compare

#pragma once
/// @file lab_tune.h
/// "Model no more than a scene needs": the cheapest method whose run stays within an error bound
/// of a tight reference run of the same scene (4x smaller time step, 4 substeps, 32 iterations).

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lab/lab_method.h"
#include "scene/params.h"
#include "scene/scene.h"

namespace impulse2d::lab {

/// How `tune_scene` measures the error against the reference.
enum class TuneMetric {
  Final,       ///< largest distance of a body from its reference position at the end, m
  Trajectory,  ///< largest such distance over samples about every 0.1 s, m
};

/// What to tune for.
struct TuneOptions {
  double max_error = 0.01;           ///< metres
  TuneMetric metric = TuneMetric::Final;  ///< how the error is measured
  double duration = 10.0;            ///< simulated seconds
  bool quick = false;                ///< a smaller search space
  int repeats = 3;                   ///< timed repeats per passing candidate (interleaved)
  /// Called after each run with (runs done, runs at most); may be empty.
  std::function<void(std::int64_t, std::int64_t)> progress;
};

/// Runs `tune_scene` makes at most with `candidates` candidates and `repeats` repeats: the
/// reference, the scene's own method and each candidate once, then every one of them timed.
std::int64_t tune_runs(std::size_t candidates, int repeats);

/// One candidate of the search.
struct TuneCandidate {
  LabMethod method;              ///< the configuration
  double error = 0.0;            ///< against the reference, m (infinity when it diverged)
  double us_per_simulated_second = 0.0;  ///< median cost (0 when not timed: failed the bound)
};

/// The answer of `tune_scene`.
struct TuneResult {
  TuneCandidate chosen;          ///< the cheapest candidate within the bound
  TuneCandidate scene_default;   ///< the scene's own method
  TuneCandidate reference;       ///< the tight reference run (error 0 by definition)
  std::vector<TuneCandidate> candidates;  ///< every candidate, in search order
  bool found = false;            ///< false when no candidate met the bound
};

/// The candidates searched for `scene`: solvers x iterations x substeps, position corrections
/// and time steps (the time step stays the scene's when it has events or a script, since those
/// are counted in steps). In a fixed order.
std::vector<LabMethod> tune_candidates(const demos::Scene& scene, bool quick);

/// The reference method: the scene's own with a 4x smaller step, 4 substeps, 32 iterations.
LabMethod tune_reference(const demos::Scene& scene);

/// The error of `method` against `reference` on `scene` (both run for `duration`).
double tune_error(const demos::Scene& scene, const demos::Params& params, const LabMethod& method,
                  const LabMethod& reference, TuneMetric metric, double duration);

/// Searches the candidates and times those that meet the bound.
TuneResult tune_scene(const demos::Scene& scene, const demos::Params& params,
                      const TuneOptions& options);

/// `{"settings": {...}, "model": {...}}` of `method` for a scene file with `model` switches, ready
/// to paste (float settings in their shortest form: a time step of 1/60 s as 0.016666668).
nlohmann::ordered_json tuned_settings(const LabMethod& method, const demos::SceneModel& model);

}  // namespace impulse2d::lab

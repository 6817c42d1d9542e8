// `tune`: its answer meets the error bound it was given (re-measured independently), it is the
// cheapest timed candidate within the bound, and an impossible bound finds nothing.
#include <gtest/gtest.h>

#include "lab/lab_scenario.h"
#include "lab/lab_tune.h"

namespace impulse2d::lab {
namespace {

demos::Scene stack_scene() {
  return load_lab_scenario(default_scenario_directory() + "/stack_10.json").scene;
}

TEST(LabTune, AnswerMeetsTheErrorBoundItWasGiven) {
  const demos::Scene scene = stack_scene();
  const demos::Params params(scene.params);
  TuneOptions options;
  options.max_error = 0.05;
  options.metric = TuneMetric::Trajectory;
  options.duration = 3.0;
  options.quick = true;
  options.repeats = 1;
  const TuneResult result = tune_scene(scene, params, options);
  ASSERT_TRUE(result.found);
  const double error = tune_error(scene, params, result.chosen.method, result.reference.method,
                                  options.metric, options.duration);
  EXPECT_LE(error, options.max_error);
  EXPECT_EQ(error, result.chosen.error);  // deterministic: the same runs give the same error
  for (const TuneCandidate& candidate : result.candidates) {
    if (candidate.error <= options.max_error) {
      EXPECT_GE(candidate.us_per_simulated_second, result.chosen.us_per_simulated_second);
    } else {
      EXPECT_EQ(candidate.us_per_simulated_second, 0.0);  // failing candidates are not timed
    }
  }
}

TEST(LabTune, ReferenceAgreesWithItselfAndAnImpossibleBoundFindsNothing) {
  const demos::Scene scene = stack_scene();
  const demos::Params params(scene.params);
  const LabMethod reference = tune_reference(scene);
  EXPECT_EQ(tune_error(scene, params, reference, reference, TuneMetric::Trajectory, 2.0), 0.0);
  TuneOptions options;
  options.max_error = 1e-9;
  options.duration = 2.0;
  options.quick = true;
  options.repeats = 1;
  EXPECT_FALSE(tune_scene(scene, params, options).found);
}

}  // namespace
}  // namespace impulse2d::lab

// The lab's scenario files: every shipped file loads, bad files are reported with file, JSON
// path and reason, and the metrics reproduce known errors of known methods exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "lab/lab_peers.h"
#include "lab/lab_scenario.h"
#include "lab/lab_sweep.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

LabScenario shipped(const std::string& name) {
  return load_lab_scenario(default_scenario_directory() + "/" + name + ".json");
}

double error_of(const LabScenario& scenario, const LabMethod& method) {
  std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, method);
  return run_scenario(scenario, *simulation, true, false).error;
}

std::string failure_of(const std::string& text) {
  try {
    parse_lab_scenario(text, "bad.json");
  } catch (const demos::UsageError& error) {
    return error.what();
  }
  return "";
}

TEST(LabScenarios, EveryShippedFileLoadsWithAMetricUnitAndThreshold) {
  const std::vector<LabScenario> scenarios = load_lab_scenarios(default_scenario_directory());
  EXPECT_GE(scenarios.size(), 19u);
  for (const LabScenario& scenario : scenarios) {
    EXPECT_FALSE(scenario.metric.unit.empty()) << scenario.name;
    EXPECT_GT(scenario.metric.threshold, 0.0) << scenario.name;
    EXPECT_FALSE(scenario.answer.empty()) << scenario.name;
    EXPECT_GT(scenario.duration, 0.0) << scenario.name;
  }
}

// Semi-implicit Euler's free flight, integrated in steps of h, is
// y0 + v0 t - g t^2/2 - g t h/2: the largest distance from the exact trajectory is g T h / 2 at
// the end. h is the integration step: the time step over the method's sub-steps (the
// default's 4; accumulated impulses take one step a frame). Float rounding aside: each of the
// T / h position updates rounds by at most half an ulp of a coordinate below 16 m (2^-21 m),
// and with a constant x velocity those roundings can all lean one way.
TEST(LabScenarios, ProjectileErrorIsSemiImplicitEulersKnownError) {
  const LabScenario scenario = shipped("projectile");
  for (const LabMethod& base : {LabMethod{}, method_for(SolverMethod::Accumulated)}) {
    for (const float step : {1.0f / 60.0f, 1.0f / 240.0f}) {
      LabMethod method = base;
      method.time_step = step;
      const double h = static_cast<double>(step) / method.substeps;
      const double expected = 9.81 * scenario.duration * h / 2.0;
      const double rounding = std::ceil(scenario.duration / h) * std::ldexp(1.0, -21);
      EXPECT_NEAR(error_of(scenario, method), expected, rounding)
          << method_label(method) << ", dt " << step;
    }
  }
}

// Two discs meeting head-on, alone: one sequential impulse with e from the mixing rule gives the
// closed form, so the error is float rounding.
TEST(LabScenarios, HeadOnCollisionsMatchTheClosedForm) {
  for (const char* name : {"elastic_collision", "inelastic_collision"}) {
    EXPECT_LT(error_of(shipped(name), LabMethod{}), 1e-5) << name;
  }
}

// The exact answer follows the method's own mixing rule: with the product rule the incline's
// mu_s is 0.25 < tan 30, and the exact slide is faster; the metric still scores a few cm.
TEST(LabScenarios, SlopeAnswerFollowsTheMixingRule) {
  const LabScenario scenario = shipped("incline_slide");
  LabMethod product;
  product.friction_mixing = FrictionMixing::Product;
  product.time_step = 1.0f / 240.0f;
  EXPECT_LT(error_of(scenario, product), scenario.metric.threshold);
}

TEST(LabScenarios, BadFilesNameFilePathAndReason) {
  const std::string scene =
      R"("scene": {"bodies": [{"name": "ball", "shape": {"type": "circle", "radius": 1}, "position": [0, 0]}]})";
  EXPECT_EQ(failure_of(R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "magic", "unit": "m", "threshold": 1, "meaning": "m"}, )" + scene + "}"),
            "bad.json: metric.kind: unknown value \"magic\" (expected one of: free_flight, "
            "slope_motion, bounce_apexes, collision_1d, cradle, energy, rest, tunnel, peak_speed, "
            "pendulum_period, spring_frequency, joint_drift, rope_slack, surface_ride)");
  EXPECT_EQ(failure_of(R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "free_flight", "body": "rock", "unit": "m", "threshold": 1, "meaning": "m"}, )" + scene + "}"),
            "bad.json: metric.body: no body named \"rock\" in scene.bodies");
  EXPECT_EQ(failure_of(R"({"description": "d", "answer": "a", "duration": -1,
      "metric": {"kind": "rest", "unit": "m", "threshold": 1, "meaning": "m"}, )" + scene + "}"),
            "bad.json: duration: must be > 0, got -1");
  const std::string bad_scene = failure_of(R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "rest", "unit": "m", "threshold": 1, "meaning": "m"},
      "scene": {"bodies": [{"shape": {"type": "circle", "radius": -1}, "position": [0, 0]}]}})");
  EXPECT_EQ(bad_scene,
            "bad.json (scene): bodies[0].shape.radius: must be in 0.001..1000 (m; below 1 mm the "
            "solver's 1 cm slop swallows the body, above 1 km float positions lose millimetres), "
            "got -1");
}

}  // namespace
}  // namespace impulse2d::lab

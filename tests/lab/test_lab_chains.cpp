// The lab's chain scenarios (issue 31): the surface_ride metric scores synthetic rides whose
// error is known by construction, a chain named in a metric stands for its first link's
// creation index, impulse2d's default rides the shipped chains within their thresholds while
// tiled boxes kick the same box, and the peers build chain links one-sided (Box2D 2.4.1) or
// two-sided with smoothed seams (Chipmunk 7.0.3) on the right side.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "lab/lab_peers.h"
#include "lab/lab_scenario.h"
#include "lab/lab_sweep.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

constexpr double g = 9.81;

/// A simulation whose bodies are whatever the test sets: the metric's view of an engine.
class ScriptedSimulation : public LabSimulation {
 public:
  void step() override {}
  float time_step() const override { return 1.0f / 240.0f; }
  vec2 gravity() const override { return {0.0f, static_cast<float>(-g)}; }
  int body_count() const override { return static_cast<int>(states.size()); }
  void read_states(std::vector<BodyState>& out) const override { out = states; }
  ContactCoefficients coefficients(int, int) const override { return friction; }
  unsigned long long state_hash() const override { return 0; }

  std::vector<BodyState> states;
  ContactCoefficients friction;
};

MetricSpec ride(RideMeasure measure, bool rolls = false) {
  MetricSpec spec;
  spec.kind = MetricKind::SurfaceRide;
  spec.bodies = {1};
  spec.surface = 0;
  spec.measure = measure;
  spec.rolls = rolls;
  return spec;
}

/// A surface at `angle` (body 0) and a body on it (body 1) moving along it at `speed`.
ScriptedSimulation on_slope(float angle, float speed) {
  ScriptedSimulation simulation;
  BodyState surface;
  surface.angle = angle;
  BodyState body;
  body.velocity = {speed * std::cos(angle), speed * std::sin(angle)};
  body.mass = 1.0f;
  body.dynamic = true;
  simulation.states = {surface, body};
  return simulation;
}

// Along a 10 degree slope the speed along it is not counted; one step's kick of 3 cm/s across
// it is the error, whichever way it points.
TEST(LabChainMetrics, NormalSpeedIsTheLargestSpeedAcrossTheSurface) {
  const float angle = 10.0f * 3.14159265f / 180.0f;
  ScriptedSimulation simulation = on_slope(angle, 5.0f);
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(ride(RideMeasure::NormalSpeed), simulation);
  const vec2 normal{-std::sin(angle), std::cos(angle)};
  for (int step = 1; step <= 240; ++step) {
    const float speed = 5.0f + step * 0.01f;
    BodyState& body = simulation.states[1];
    body.velocity = {speed * std::cos(angle), speed * std::sin(angle)};
    if (step == 100) body.velocity -= 0.03f * normal;
    if (step == 101) body.velocity += 0.02f * normal;
    tracker->observe(step / 240.0, simulation.states);
  }
  EXPECT_NEAR(tracker->error(), 0.03, 1e-5);
}

TEST(LabChainMetrics, AngularSpeedIsTheLargestSpin) {
  ScriptedSimulation simulation = on_slope(0.0f, 5.0f);
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(ride(RideMeasure::AngularSpeed), simulation);
  for (int step = 1; step <= 240; ++step) {
    simulation.states[1].angular_velocity = step == 50 ? -0.4f : (step == 60 ? 0.1f : 0.0f);
    tracker->observe(step / 240.0, simulation.states);
  }
  EXPECT_NEAR(tracker->error(), 0.4, 1e-6);
}

// A disc rolling down 5 degrees from 2 m/s (mu_s 0.5 >= tan(5)/3): exact 2/3 g sin(theta), so
// the exact velocities score 0 and velocities of a 2 % faster acceleration score 2 %. With
// mu_s 0.02 < tan(5)/3 it slips: g (sin - mu_d cos) is exact instead.
TEST(LabChainMetrics, AccelerationIsScoredAgainstRollingOrSlipping) {
  const double theta = 5.0 * 3.14159265358979 / 180.0;
  const float angle = static_cast<float>(-theta);
  const auto score = [&](double acceleration, float mu_s, float mu_d) {
    ScriptedSimulation simulation = on_slope(angle, 2.0f);
    simulation.friction.static_friction = mu_s;
    simulation.friction.dynamic_friction = mu_d;
    const std::unique_ptr<MetricTracker> tracker =
        make_metric_tracker(ride(RideMeasure::Acceleration, true), simulation);
    for (int step = 1; step <= 960; ++step) {
      const double t = step / 240.0;
      const float speed = static_cast<float>(2.0 + acceleration * t);
      simulation.states[1].velocity = {speed * std::cos(angle), speed * std::sin(angle)};
      tracker->observe(t, simulation.states);
    }
    return tracker->error();
  };
  const double rolling = 2.0 / 3.0 * g * std::sin(theta);
  EXPECT_LT(score(rolling, 0.5f, 0.3f), 1e-3);
  EXPECT_NEAR(score(1.02 * rolling, 0.5f, 0.3f), 2.0, 1e-3);
  const double slipping = g * (std::sin(theta) - 0.01 * std::cos(theta));
  EXPECT_LT(score(slipping, 0.02f, 0.01f), 1e-3);
  EXPECT_GT(score(rolling, 0.02f, 0.01f), 10.0);
}

std::string failure_of(const std::string& text) {
  try {
    parse_lab_scenario(text, "bad.json");
  } catch (const demos::UsageError& error) {
    return error.what();
  }
  return "";
}

const std::string chain_body =
    R"({"name": "ground", "type": "static", "shape": {"type": "chain", "points": [[-2, 0], [-1, 0], [0, 0], [1, 0], [2, 0]]}, "position": [0, 0]})";
const std::string box_body =
    R"({"name": "box", "shape": {"type": "box", "half_extents": [0.25, 0.25]}, "position": [0, 0.25]})";

std::string ride_file(const std::string& metric_fields, const std::string& bodies) {
  return R"({"description": "d", "answer": "a", "duration": 1, "metric": {"kind": "surface_ride", )" +
         metric_fields + R"(, "unit": "m/s", "threshold": 1, "meaning": "m"}, "scene": {"bodies": [)" +
         bodies + "]}}";
}

// A chain of four links makes four bodies: named before the box it pushes the box's creation
// index to 4; named as the surface it is its first link.
TEST(LabChainScenarios, AChainCountsOneBodyPerLink) {
  const LabScenario after = parse_lab_scenario(
      ride_file(R"("body": "box", "surface": "ground", "measure": "normal_speed")", box_body + ", " + chain_body),
      "after.json");
  EXPECT_EQ(after.metric.bodies.at(0), 0);
  EXPECT_EQ(after.metric.surface, 1);
  const LabScenario before = parse_lab_scenario(
      ride_file(R"("body": "box", "surface": "ground", "measure": "normal_speed")", chain_body + ", " + box_body),
      "before.json");
  EXPECT_EQ(before.metric.bodies.at(0), 4);
  EXPECT_EQ(before.metric.surface, 0);
  EXPECT_EQ(before.metric.measure, RideMeasure::NormalSpeed);
}

TEST(LabChainScenarios, BadRideMetricsNameTheField) {
  const std::string bodies = box_body + ", " + chain_body;
  EXPECT_EQ(failure_of(ride_file(R"("body": "box", "surface": "ground")", bodies)),
            "bad.json: metric: metric needs \"measure\" (normal_speed, angular_speed or acceleration)");
  EXPECT_EQ(failure_of(ride_file(R"("body": "box", "measure": "normal_speed")", bodies)),
            "bad.json: metric: metric needs \"surface\"");
  EXPECT_EQ(failure_of(ride_file(R"("body": "box", "surface": "ground", "measure": "bumps")", bodies)),
            "bad.json: metric.measure: unknown value \"bumps\" (expected one of: normal_speed, "
            "angular_speed, acceleration)");
  EXPECT_EQ(failure_of(R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "rest", "measure": "normal_speed", "unit": "m", "threshold": 1, "meaning": "m"},
      "scene": {"bodies": [)" + bodies + "]}}"),
            "bad.json: metric.measure: only a surface_ride metric takes \"measure\"");
  EXPECT_EQ(failure_of(ride_file(R"("body": "box", "surface": "ground", "measure": "acceleration", "after": 1)", bodies)),
            "bad.json: metric.after: the acceleration measure is the mean over the whole run: no \"after\"");
}

// `after` leaves the start out of the speeds: a 5 cm/s settling in the first 0.2 s does not
// count from 0.25 s on, a 1 mm/s kick at 0.5 s does.
TEST(LabChainMetrics, SpeedsCountFromAfter) {
  ScriptedSimulation simulation = on_slope(0.0f, 5.0f);
  MetricSpec spec = ride(RideMeasure::NormalSpeed);
  spec.after = 0.25;
  const std::unique_ptr<MetricTracker> tracker = make_metric_tracker(spec, simulation);
  for (int step = 1; step <= 240; ++step) {
    const double t = step / 240.0;
    simulation.states[1].velocity.y = t < 0.2 ? -0.05f : (step == 120 ? 0.001f : 0.0f);
    tracker->observe(t, simulation.states);
  }
  EXPECT_NEAR(tracker->error(), 0.001, 1e-7);
}

LabScenario shipped(const std::string& name) {
  return load_lab_scenario(default_scenario_directory() + "/" + name + ".json");
}

double error_of(const LabScenario& scenario, const LabMethod& method) {
  std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, method);
  return run_scenario(scenario, *simulation, true, false).error;
}

// impulse2d's default slides across the shipped chain's seams and rolls down the chain slope
// within the thresholds; the same slide on tiled boxes is kicked at the seams (the ghost
// collision the chain removes) by far more.
TEST(LabChainScenarios, DefaultRidesTheChainsAndTilesKick) {
  const LabMethod method;  // WorldSettings' defaults
  for (const char* name :
       {"seam_slide", "seam_slide_spin", "seam_slide_stop", "chain_roll", "chain_roll_bump"}) {
    const LabScenario scenario = shipped(name);
    const double error = error_of(scenario, method);
    std::printf("%s: %.3g %s (threshold %g)\n", name, error, scenario.metric.unit.c_str(),
                scenario.metric.threshold);
    EXPECT_LE(error, scenario.metric.threshold) << name;
  }
  const double tiles = error_of(shipped("seam_slide_tiles"), method);
  const double chain = error_of(shipped("seam_slide"), method);
  std::printf("seam_slide_tiles: %.3g m/s against the chain's %.3g m/s\n", tiles, chain);
  EXPECT_GT(tiles, 0.1);
  EXPECT_GT(tiles, 1000.0 * chain);
}

/// A ball flying at 5 m/s without gravity through the chain from `from_y` (a free_flight
/// metric: its error is how far the chain turned it from the straight line).
LabScenario ball_through_chain(float from_y) {
  const std::string text =
      R"({"description": "d", "answer": "a", "duration": 1,
          "metric": {"kind": "free_flight", "body": "ball", "unit": "m", "threshold": 0.01, "meaning": "m"},
          "scene": {"settings": {"gravity": [0, 0]},
                    "bodies": [{"name": "ball", "shape": {"type": "circle", "radius": 0.1},
                                "position": [0.3, )" + std::to_string(from_y) + R"(], "velocity": [0, )" +
      std::to_string(from_y < 0.0f ? 5.0 : -5.0) + R"(]}, )" + chain_body + "]}}";
  return parse_lab_scenario(text, from_y < 0.0f ? "from_below.json" : "from_above.json");
}

// A chain listed left to right faces up: every engine stops a ball coming down on it; a ball
// coming up from below passes impulse2d's and Box2D 2.4.1's one-sided links (a wrong point
// order in the Box2D adapter would swap the two) and is stopped by Chipmunk 7.0.3's two-sided
// segments. Measured: stopped 4.92 m (4.25 m in Chipmunk) off the line; passing, impulse2d
// 7e-6 m, Box2D 0.021 m.
TEST(LabChainPeers, ChainLinksFaceTheSameWayInEveryEngine) {
  std::vector<LabMethod> methods = peer_methods(1.0f / 60.0f);
  methods.insert(methods.begin(), LabMethod());
  for (const LabMethod& method : methods) {
    if (!engine_available(method.engine)) {
      std::printf("%s skipped: %s\n", engine_name(method.engine), engine_note(method.engine).c_str());
      continue;
    }
    const double from_above = error_of(ball_through_chain(1.0f), method);
    const double from_below = error_of(ball_through_chain(-1.0f), method);
    std::printf("%s: from above %.3g m off the straight line, from below %.3g m\n",
                engine_name(method.engine), from_above, from_below);
    EXPECT_GT(from_above, 1.0) << engine_name(method.engine);
    if (method.engine == Engine::Chipmunk) {
      EXPECT_GT(from_below, 1.0) << engine_name(method.engine);
    } else {
      // Box2D's time of impact ignores one-sidedness: the ball is stopped at the link's back at
      // its time of impact (2.1 cm behind the straight line), then passes.
      EXPECT_LT(from_below, method.engine == Engine::Box2d ? 0.05 : 1e-4) << engine_name(method.engine);
    }
  }
}

// Box2D 2.4.1's one-sided edges with ghost vertices slide the box across 100 seams and roll
// the disc down the chain slope without a seam kick (both within the 1e-4 m/s threshold), and
// Chipmunk 7.0.3's neighbours smooth the disc's seams. Chipmunk's box on the same chain is not
// asserted: its neighbour test drops some of the box's contacts and the box sinks 2 cm and
// rocks (0.98 m/s, measured in docs/lab.md's Chains table).
TEST(LabChainPeers, PeersRideTheChain) {
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) continue;
    const double bump = error_of(shipped("seam_slide"), peer);
    const double spin = error_of(shipped("seam_slide_spin"), peer);
    const double roll = error_of(shipped("chain_roll_bump"), peer);
    std::printf("%s: seam_slide %.3g m/s, spin %.3g rad/s, chain_roll_bump %.3g m/s\n",
                engine_name(peer.engine), bump, spin, roll);
    EXPECT_LT(roll, 1e-4) << engine_name(peer.engine);
    if (peer.engine == Engine::Box2d) {
      EXPECT_LT(bump, 1e-4);
      EXPECT_LT(spin, 4e-4);
    }
  }
}

}  // namespace
}  // namespace impulse2d::lab

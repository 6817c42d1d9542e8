// The lab's joint metrics (pendulum period, spring frequency, joint drift, slack rope): each
// scores a synthetic trajectory whose error is known by construction, and the peers' joint
// mapping is checked on the shipped pendulum (Box2D 2.4.1 and Chipmunk 7.0.3 swing it within a
// few percent of the exact period, which a wrong anchor, length or body would not).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "lab/lab_peers.h"
#include "lab/lab_scenario.h"
#include "lab/lab_sweep.h"
#include "demos/scene_registry.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double g = 9.81;

/// A simulation whose bodies are whatever the test sets: the metric's view of an engine.
class ScriptedSimulation : public LabSimulation {
 public:
  void step() override {}
  float time_step() const override { return 1.0f / 240.0f; }
  vec2 gravity() const override { return {0.0f, static_cast<float>(-g)}; }
  int body_count() const override { return static_cast<int>(states.size()); }
  void read_states(std::vector<BodyState>& out) const override { out = states; }
  ContactCoefficients coefficients(int, int) const override { return {}; }
  unsigned long long state_hash() const override { return 0; }
  const std::vector<LabJoint>& joints() const override { return lab_joints; }

  std::vector<BodyState> states;
  std::vector<LabJoint> lab_joints;
};

BodyState static_body(vec2 position) {
  BodyState state;
  state.position = position;
  return state;
}

BodyState bob_at(vec2 position, vec2 velocity = {0.0f, 0.0f}) {
  BodyState state;
  state.position = position;
  state.velocity = velocity;
  state.mass = 1.0f;
  state.dynamic = true;
  return state;
}

LabJoint joint_between(JointType type, int a, int b, vec2 local_a, vec2 local_b) {
  LabJoint joint;
  joint.spec.type = type;
  joint.body_a = a;
  joint.body_b = b;
  joint.local_anchor_a = local_a;
  joint.local_anchor_b = local_b;
  return joint;
}

MetricSpec metric(MetricKind kind, std::vector<int> bodies, std::vector<int> joints) {
  MetricSpec spec;
  spec.kind = kind;
  spec.bodies = std::move(bodies);
  spec.joints = std::move(joints);
  return spec;
}

// The period the metric takes as exact: 2 pi sqrt(L/g) (1 + theta0^2/16) for small swings
// (the series' next term, 11/3072 theta0^4, is 4e-7 at 0.1 rad) and 4 sqrt(L/g) K(1/sqrt 2)
// with K(1/sqrt 2) = 1.8540746773 (tables) from 90 degrees.
TEST(LabJointMetrics, ExactPendulumPeriodMatchesTheSeriesAndTheTable) {
  const double small = 2.0 * pi * std::sqrt(1.0 / g) * (1.0 + 0.01 / 16.0);
  EXPECT_NEAR(exact_pendulum_period(1.0, g, 0.1) / small, 1.0, 1e-6);
  EXPECT_NEAR(exact_pendulum_period(2.0, g, pi / 2.0), 4.0 * std::sqrt(2.0 / g) * 1.8540746773,
              1e-9);
}

// A pendulum swinging as theta0 cos(2 pi t / T') with T' = 1.02 T (2 % slow): the metric reads
// 2 %, to the interpolation of crossings between 240 Hz samples.
TEST(LabJointMetrics, PendulumPeriodErrorOfASyntheticSwing) {
  for (const double theta0 : {0.1, pi / 2.0}) {
    const double length = 1.0;
    ScriptedSimulation simulation;
    simulation.states = {static_body({0.0f, 0.0f}),
                         bob_at({static_cast<float>(length * std::sin(theta0)),
                                 static_cast<float>(-length * std::cos(theta0))})};
    simulation.lab_joints = {joint_between(JointType::Revolute, 0, 1, {0.0f, 0.0f},
                                           simulation.states[1].position)};
    const std::unique_ptr<MetricTracker> tracker =
        make_metric_tracker(metric(MetricKind::PendulumPeriod, {1}, {0}), simulation);
    const double period = 1.02 * exact_pendulum_period(length, g, theta0);
    for (int step = 1; step <= 2400; ++step) {
      const double t = step / 240.0;
      const double theta = theta0 * std::cos(2.0 * pi * t / period);
      simulation.states[1].position = {static_cast<float>(length * std::sin(theta)),
                                       static_cast<float>(-length * std::cos(theta))};
      tracker->observe(t, simulation.states);
    }
    EXPECT_NEAR(tracker->error(), 2.0, 0.01) << theta0;
  }
}

// A bob that never swings has no period: the error is 100 %, not 0.
TEST(LabJointMetrics, PendulumThatNeverCrossesScoresAHundredPercent) {
  ScriptedSimulation simulation;
  simulation.states = {static_body({0.0f, 0.0f}), bob_at({0.1f, -1.0f})};
  simulation.lab_joints = {joint_between(JointType::Revolute, 0, 1, {0.0f, 0.0f}, {-0.1f, 1.0f})};
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(metric(MetricKind::PendulumPeriod, {1}, {0}), simulation);
  for (int step = 1; step <= 240; ++step) tracker->observe(step / 240.0, simulation.states);
  EXPECT_EQ(tracker->error(), 100.0);
}

// A bob bouncing on a 2 Hz spring at 2.06 Hz (3 % fast) around a centre below the rest length
// (gravity's shift): the turning points give 3 %.
TEST(LabJointMetrics, SpringFrequencyErrorOfASyntheticOscillation) {
  ScriptedSimulation simulation;
  simulation.states = {static_body({0.0f, 0.0f}), bob_at({0.0f, -1.0f})};
  LabJoint spring = joint_between(JointType::Distance, 0, 1, {0.0f, 0.0f}, {0.0f, 0.0f});
  spring.spec.distance.enable_spring = true;
  spring.spec.distance.hertz = 2.0f;
  simulation.lab_joints = {spring};
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(metric(MetricKind::SpringFrequency, {}, {0}), simulation);
  const double f = 2.06, omega = 2.0 * pi * f, amplitude = 0.06;
  for (int step = 1; step <= 1200; ++step) {
    const double t = step / 240.0;
    simulation.states[1].position = {0.0f, static_cast<float>(-1.06 + amplitude * std::cos(omega * t))};
    simulation.states[1].velocity = {0.0f, static_cast<float>(-amplitude * omega * std::sin(omega * t))};
    tracker->observe(t, simulation.states);
  }
  EXPECT_NEAR(tracker->error(), 3.0, 0.01);
}

// Two hinges and a rigid distance joint: the drift is the largest separation ever seen (a
// 4 mm slip of the middle link's anchor at one step), and the distance joint's is its length
// error (a 3 mm stretch of a 0.5 m joint at another step, below the slip).
TEST(LabJointMetrics, JointDriftIsTheLargestAnchorSeparationOverTheRun) {
  ScriptedSimulation simulation;
  simulation.states = {static_body({0.0f, 0.0f}), bob_at({0.0f, -0.25f}), bob_at({0.0f, -0.5f}),
                       bob_at({0.5f, -0.5f})};
  LabJoint rod = joint_between(JointType::Distance, 2, 3, {0.0f, 0.0f}, {0.0f, 0.0f});
  rod.spec.distance.length = 0.5f;
  simulation.lab_joints = {joint_between(JointType::Revolute, 0, 1, {0.0f, 0.0f}, {0.0f, 0.25f}),
                           joint_between(JointType::Revolute, 1, 2, {0.0f, -0.125f}, {0.0f, 0.125f}),
                           rod};
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(metric(MetricKind::JointDrift, {}, {}), simulation);
  tracker->observe(1.0 / 60.0, simulation.states);
  EXPECT_NEAR(tracker->error(), 0.0, 1e-7);
  simulation.states[2].position.y -= 0.004f;  // the second hinge opens by 4 mm
  simulation.states[3].position.y -= 0.004f;
  tracker->observe(2.0 / 60.0, simulation.states);
  simulation.states[2].position.y += 0.004f;
  simulation.states[3].position = {0.503f, -0.5f};  // the rod stretches by 3 mm
  tracker->observe(3.0 / 60.0, simulation.states);
  EXPECT_NEAR(tracker->error(), 0.004, 1e-6);
  // Counting from 2.5 steps on ("after"), the slip is not seen: the rod's 3 mm.
  MetricSpec settled = metric(MetricKind::JointDrift, {}, {});
  settled.after = 2.5 / 60.0;
  const std::unique_ptr<MetricTracker> late = make_metric_tracker(settled, simulation);
  simulation.states[2].position.y -= 0.004f;
  late->observe(2.0 / 60.0, simulation.states);
  simulation.states[2].position.y += 0.004f;
  late->observe(3.0 / 60.0, simulation.states);
  EXPECT_NEAR(late->error(), 0.003, 1e-6);
  // Only the rod: its 3 mm.
  const std::unique_ptr<MetricTracker> rod_only =
      make_metric_tracker(metric(MetricKind::JointDrift, {}, {2}), simulation);
  rod_only->observe(4.0 / 60.0, simulation.states);
  EXPECT_NEAR(rod_only->error(), 0.003, 1e-6);
}

// A ball thrown on a slack 1 m rope: while the exact free fall stays within the rope it must
// fly free (a 2 cm kick then is the error); once the rope would be taut, it may act.
TEST(LabJointMetrics, RopeSlackScoresOnlyWhileTheRopeIsSlack) {
  ScriptedSimulation simulation;
  const vec2 p0{-0.3f, -0.2f}, v0{1.5f, 1.0f};
  simulation.states = {static_body({0.0f, 0.0f}), bob_at(p0, v0)};
  LabJoint rope = joint_between(JointType::Distance, 0, 1, {0.0f, 0.0f}, {0.0f, 0.0f});
  rope.spec.distance.enable_spring = true;
  rope.spec.distance.enable_limit = true;
  rope.spec.distance.max_length = 1.0f;
  simulation.lab_joints = {rope};
  const std::unique_ptr<MetricTracker> tracker =
      make_metric_tracker(metric(MetricKind::RopeSlack, {1}, {0}), simulation);
  bool kicked = false;
  for (int step = 1; step <= 240; ++step) {
    const double t = step / 120.0;
    vec2 p{static_cast<float>(p0.x + v0.x * t), static_cast<float>(p0.y + v0.y * t - 0.5 * g * t * t)};
    const double reach = std::hypot(p.x, p.y);
    if (reach > 1.0) p = p / static_cast<float>(reach) * 0.9f;  // caught: far off free fall
    if (!kicked && t > 0.2) {
      p.x += 0.02f;
      kicked = true;
    }
    simulation.states[1].position = p;
    tracker->observe(t, simulation.states);
  }
  EXPECT_NEAR(tracker->error(), 0.02, 1e-5);
}

// A metric naming a joint the scene lacks, or one of the wrong type, is refused with its path.
TEST(LabJointMetrics, MetricJointsAreCheckedWhenTheFileIsRead) {
  const std::string scene =
      R"("scene": {"bodies": [{"name": "pivot", "type": "static", "shape": {"type": "circle", "radius": 0.05}, "position": [0, 0]},
                              {"name": "bob", "shape": {"type": "circle", "radius": 0.05}, "position": [1, 0]}],
                   "joints": [{"type": "weld", "name": "glue", "bodies": ["pivot", "bob"], "anchor": [0, 0]}]}})";
  const auto failure = [&](const std::string& metric_text) {
    try {
      parse_lab_scenario(R"({"description": "d", "answer": "a", "duration": 1, "metric": )" +
                             metric_text + ", " + scene,
                         "bad.json");
    } catch (const demos::UsageError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(failure(R"({"kind": "pendulum_period", "body": "bob", "joint": "hinge", "unit": "%", "threshold": 1, "meaning": "m"})")
                .find("no joint named \"hinge\""),
            std::string::npos);
  EXPECT_NE(failure(R"({"kind": "pendulum_period", "body": "bob", "joint": "glue", "unit": "%", "threshold": 1, "meaning": "m"})")
                .find("is a weld joint; the metric needs a revolute or distance joint"),
            std::string::npos);
  EXPECT_NE(failure(R"({"kind": "spring_frequency", "unit": "%", "threshold": 1, "meaning": "m"})")
                .find("metric needs \"joint\""),
            std::string::npos);
  EXPECT_EQ(failure(R"({"kind": "joint_drift", "unit": "m", "threshold": 1, "meaning": "m"})"), "");
}

LabScenario shipped(const std::string& name) {
  return load_lab_scenario(default_scenario_directory() + "/" + name + ".json");
}

double error_of(const LabScenario& scenario, const LabMethod& method) {
  std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, method);
  return run_scenario(scenario, *simulation, true, false).error;
}

// The peers build the scene's hinge: Box2D 2.4.1 and Chipmunk 7.0.3 swing the shipped small
// pendulum within 0.1 % of the exact period (measured 0.011 % and 0.0068 %), where a wrong
// anchor, arm or body would be percents off (the same bob on a 1.1 m arm swings 4.9 % slower,
// a bob that cannot turn does not swing at all). From 90 degrees both lose energy: the swing
// decays (to 60 degrees in Box2D's 10 s, 73 in Chipmunk's, while impulse2d keeps 89.9) and a
// smaller swing is a shorter period: 6.5 % and 3.4 % off, pinned within 10 % here.
TEST(LabJointPeers, PeersSwingThePendulumAtTheExactPeriod) {
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) {
      std::printf("%s skipped: %s\n", engine_name(peer.engine), engine_note(peer.engine).c_str());
      continue;
    }
    const double small = error_of(shipped("pendulum_small"), peer);
    const double large = error_of(shipped("pendulum_large"), peer);
    std::printf("%s period error %.4f %% (small), %.4f %% (large)\n", engine_name(peer.engine), small,
                large);
    EXPECT_LT(small, 0.1) << engine_name(peer.engine);
    EXPECT_LT(large, 10.0) << engine_name(peer.engine);
  }
}

// The peers' springs: the joint's f Hz becomes stiffness m (2 pi f)^2 on the bob, so each
// engine bounces the shipped spring within 3 % of 2 Hz.
TEST(LabJointPeers, PeersBounceTheSpringAtItsFrequency) {
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) continue;
    const double error = error_of(shipped("spring_mass"), peer);
    std::printf("%s spring frequency error %.4f %%\n", engine_name(peer.engine), error);
    EXPECT_LT(error, 3.0) << engine_name(peer.engine);
  }
}

// The peers' prismatic joint keeps the disc on the 30 degree axis: it slides as semi-implicit
// Euler's free slide does, a T h / 2 = 4.905 * 2 / 60 / 2 = 0.0818 m behind the exact
// position after 2 s at one step a frame (an axis mapped wrong would be metres off); the
// peers' weld (Box2D's b2WeldJoint, Chipmunk's pivot + gear) holds the cantilever within 1 mm.
TEST(LabJointPeers, PeersSlideOnThePrismaticAxisAndHoldTheWeld) {
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) continue;
    const double slide = error_of(shipped("prismatic_slide"), peer);
    const double weld = error_of(shipped("weld_cantilever"), peer);
    std::printf("%s prismatic %.5f m, weld %.3g m\n", engine_name(peer.engine), slide, weld);
    EXPECT_NEAR(slide, 4.905 * 2.0 / 60.0 / 2.0, 1e-3) << engine_name(peer.engine);
    EXPECT_LT(weld, 1e-3) << engine_name(peer.engine);
  }
}

// A revolute motor of +2 rad/s (B counter-clockwise relative to A) with a wide limit: each
// peer spins the disc at +2 rad/s after half a second (Chipmunk's cpSimpleMotor takes the
// opposite sign; Box2D's and Chipmunk's rotary limits are absolute angles, offset by the
// reference angle).
TEST(LabJointPeers, PeersDriveTheRevoluteMotorAtItsSpeed) {
  const LabScenario scenario = parse_lab_scenario(R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "joint_drift", "unit": "m", "threshold": 1, "meaning": "m"},
      "scene": {"settings": {"gravity": [0, 0]}, "model": {"shapes": ["circle"], "rotation": true},
                "bodies": [{"name": "a", "type": "static", "shape": {"type": "circle", "radius": 0.05}, "position": [0, 0]},
                           {"name": "b", "shape": {"type": "circle", "radius": 0.2}, "position": [0, 0]}],
                "joints": [{"type": "revolute", "bodies": ["a", "b"], "anchor": [0, 0],
                            "motor": {"speed": 2.0, "max_torque": 100}, "limits": [-100, 100]}]}})",
                                                  "motor.json");
  std::vector<LabMethod> methods = peer_methods(1.0f / 60.0f);
  methods.push_back(LabMethod{});
  for (const LabMethod& method : methods) {
    if (!engine_available(method.engine)) continue;
    std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, method);
    for (int step = 0; step < 30; ++step) simulation->step();
    std::vector<BodyState> states;
    simulation->read_states(states);
    EXPECT_NEAR(states[1].angular_velocity, 2.0f, 1e-3f) << engine_name(method.engine);
  }
}

// A joint a peer lacks fails the run with its name, never silently dropped: Chipmunk has no
// wheel joint, Box2D 2.4.1 no revolute spring.
TEST(LabJointPeers, AJointThePeerLacksIsReportedNotDropped) {
  const std::string text = R"({"description": "d", "answer": "a", "duration": 1,
      "metric": {"kind": "joint_drift", "unit": "m", "threshold": 1, "meaning": "m"},
      "scene": {"bodies": [{"name": "a", "type": "static", "shape": {"type": "circle", "radius": 0.05}, "position": [0, 0]},
                           {"name": "b", "shape": {"type": "circle", "radius": 0.05}, "position": [1, 0]}],
                "joints": [{"type": "JOINT", "bodies": ["a", "b"], "anchor": [0, 0],
                            "spring": {"hertz": 2, "damping_ratio": 0.5}}]}})";
  const auto with_joint = [&](const std::string& type) {
    std::string scenario = text;
    // `JOINT"` becomes `revolute"` or `wheel", "axis": [0, 1]` (a wheel needs its axis).
    scenario.replace(scenario.find("JOINT\""), 6,
                     type + "\"" + (type == "wheel" ? R"(, "axis": [0, 1])" : ""));
    return parse_lab_scenario(scenario, "joint.json");
  };
  const auto failure = [](const LabScenario& scenario, const LabMethod& method) {
    try {
      make_simulation(scenario.scene, method);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) continue;
    if (peer.engine == Engine::Chipmunk) {
      EXPECT_NE(failure(with_joint("wheel"), peer).find("not supported by Chipmunk 7.0.3"),
                std::string::npos);
      EXPECT_EQ(failure(with_joint("revolute"), peer), "");  // cpDampedRotarySpring
    } else {
      EXPECT_NE(failure(with_joint("revolute"), peer).find("not supported by Box2D 2.4.1"),
                std::string::npos);
      EXPECT_EQ(failure(with_joint("wheel"), peer), "");
    }
  }
}

// A built-in scene whose code makes its joints (heavy_chain): impulse2d runs it, the peers
// refuse it by name instead of running the links unjoined.
TEST(LabJointPeers, JointsMadeByASceneCodeAreRefusedByThePeers) {
  const demos::Scene* scene = demos::find_builtin_scene("heavy_chain");
  ASSERT_NE(scene, nullptr);
  EXPECT_NE(make_simulation(*scene, LabMethod{}), nullptr);
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (!engine_available(peer.engine)) continue;
    try {
      make_simulation(*scene, peer);
      ADD_FAILURE() << engine_name(peer.engine) << " ran heavy_chain without its joints";
    } catch (const std::runtime_error& error) {
      EXPECT_NE(std::string(error.what()).find("joints made by the scene's code"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace impulse2d::lab

/// @file test_golden_verdicts.cpp
/// The verdict at the edges (issue 29), where a reviewer relies on it:
/// - the set of living bodies is part of the noise envelope: bodies are matched by creation
///   order, not by world slot, and a body some perturbed run removed (or kept) may be
///   missing (or extra) in a later run: the tutorial scene, which spawns and removes bodies,
///   is *numerical noise* under a one-ulp change of gravity and under a reordered sum;
/// - three real changes that moved bodies by up to metres in chaotic scenes (a friction
///   mixing rule, the restitution threshold -10 %, slop +5 %) are *behaviour changed* or
///   *cannot tell*, never *numerical noise*, and the cannot-tell message names the step
///   from which the scene stops telling.
/// Variants never write goldens or artifacts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <iostream>
#include <string>
#include <vector>

#include "core/world.h"
#include "golden/scenes/golden_block.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/golden_run.h"
#include "golden/scenes/noise_probe.h"
#include "golden/scenes/scene_frame.h"
#include "render/frame_renderer.h"
#include "scene/scene.h"
#include "tests/golden/test_golden_support.h"

namespace impulse2d::golden {
namespace {

/// What a run of a golden's scene records for the judgement (no rendering).
struct Physics {
  std::vector<BodyPose> bodies;
  std::vector<PhysicsSample> samples;
};

Physics run_physics(const GoldenSpec& spec, const SceneVariant& variant = nullptr) {
  GoldenRun run(spec, variant);
  Physics physics;
  for (const std::int64_t checkpoint : noise_checkpoint_steps(spec.step)) {
    while (run.run().step_count() < checkpoint) run.step();
    physics.samples.push_back(sample_physics(run.world()));
  }
  physics.bodies = run.body_poses();
  return physics;
}

/// The class `classify_failure` gives a verdict once the state hashes differ.
FailureClass class_of(const NoiseVerdict& verdict) {
  if (!verdict.within()) return FailureClass::BehaviourChanged;
  return verdict.cannot_tell() ? FailureClass::CannotTell : FailureClass::NumericalNoise;
}

const GoldenSpec& builtin(const std::string& id) {
  const GoldenSpec* spec = find_golden(id);
  if (spec == nullptr) throw std::logic_error("no golden " + id);
  return *spec;
}

/// Gravity's y one ulp smaller in magnitude (as a rounding change of the constant would be).
void gravity_one_ulp_smaller(demos::Scene& scene) {
  scene.settings.gravity.y = std::nextafter(scene.settings.gravity.y, 0.0f);
}

/// Judges `spec` run with `change` against a freshly measured envelope (this build's probe:
/// bodies by creation order, the living set, the per-step spread), printing the verdict.
NoiseVerdict judge_fresh(const GoldenSpec& spec, const SceneVariant& change) {
  const NoiseEnvelope envelope = measure_noise_envelope(spec);
  const Physics golden = run_physics(spec);
  const Physics changed = run_physics(spec, change);
  const NoiseVerdict verdict =
      judge_against_envelope(envelope, golden.bodies, changed.bodies, changed.samples);
  std::cout << spec.id() << " at step " << spec.step << ": "
            << failure_class_name(class_of(verdict)) << ": " << verdict.describe(3)
            << "; largest move " << verdict.largest_move << " m (" << verdict.largest_move_body
            << "), envelope reach " << verdict.envelope_reach << " m, bound " << verdict.bound
            << " m, stops telling at step " << verdict.stops_telling_step << "\n";
  return verdict;
}

// The tutorial removes bodies that fall off and spawns new ones; a run whose rounding differs
// removes some a step earlier or later, and reuses other slots. Matched by creation order and
// with the living set in the envelope, a one-ulp change of gravity never leaves the envelope
// (before issue 29: "behaviour changed: body 8 (generation 2) (missing in this run)").
// Where the scene has not yet amplified rounding beyond 1 % of its size it is numerical noise;
// at the committed frames (steps 240 and 900) the scene already amplifies one ulp to metres,
// so the honest verdict there is "cannot tell", with the step from which it stops telling.
TEST(GoldenVerdicts, TutorialOneUlpGravityStaysInsideTheEnvelopeThoughBodiesComeAndGo) {
  GoldenSpec early = builtin("tutorial/motion");
  early.step = 210;
  {
    const GoldenSpec& settled = builtin("tutorial/settled");
    GoldenRun run(settled);
    while (run.run().step_count() < settled.step) run.step();
    const std::vector<BodyPose> alive = run.body_poses();
    // Bodies were removed by the settled frame (the last creation index is beyond the
    // living count), so the living set is part of what is judged there.
    int last = 0;
    for (const BodyPose& pose : alive) {
      const std::size_t hash = pose.name.find('#');
      last = std::max(last, std::stoi(pose.name.substr(hash + 1)));
    }
    EXPECT_GT(last + 1, static_cast<int>(alive.size())) << "no body removed by step 900";
  }
  const NoiseVerdict at_210 = judge_fresh(early, gravity_one_ulp_smaller);
  EXPECT_EQ(class_of(at_210), FailureClass::NumericalNoise) << at_210.describe(5);

  for (const char* id : {"tutorial/motion", "tutorial/settled"}) {
    const NoiseVerdict verdict = judge_fresh(builtin(id), gravity_one_ulp_smaller);
    EXPECT_TRUE(verdict.within()) << id << ": " << verdict.describe(5);
    EXPECT_EQ(class_of(verdict), FailureClass::CannotTell) << id;
    EXPECT_GT(verdict.stops_telling_step, 0) << id;
    EXPECT_LE(verdict.stops_telling_step, builtin(id).step) << id;
    const std::string text = verdict.describe_cannot_tell();
    EXPECT_NE(text.find("from step " + std::to_string(verdict.stops_telling_step)),
              std::string::npos)
        << text;
  }
}

/// A real change, the goldens it moved bodies in (by up to metres, in chaotic scenes), and
/// where those goldens live.
struct RealChange {
  std::string name;
  std::vector<std::string> goldens;
  SceneVariant change;
  std::string scene_file;  ///< empty: built-in goldens
};

void PrintTo(const RealChange& change, std::ostream* out) { *out << change.name; }

class RealChanges : public ::testing::TestWithParam<RealChange> {};

/// Checks `golden` of `scene_file` against its committed golden, the scene run with `change`
/// (no update, no artifacts).
CheckOutcome check_scene_file_variant(const std::string& scene_file, const std::string& golden,
                                      const SceneVariant& change) {
  const SceneGoldens goldens = read_scene_goldens(scene_file);
  for (const GoldenSpec& spec : goldens.frames) {
    if (spec.id() != golden) continue;
    CheckSettings settings;
    settings.golden_dir = goldens.golden_dir;
    settings.tolerance = goldens.tolerance;
    render::FrameRenderer renderer(spec.width, spec.height);
    return run_golden_check(spec.id(), spec.scene, static_cast<int>(spec.step),
                            [&] { return produce_scene_frame(spec, renderer, change); }, settings);
  }
  throw std::logic_error(scene_file + " has no golden " + golden);
}

// Issue 29: each of these was classed "numerical noise ... review the images and promote".
// Against the committed sidecars (and their envelopes) every golden whose physics they change
// is now "behaviour changed" or "cannot tell", never noise and never with the advice to
// promote; each change reaches at least one of its goldens.
TEST_P(RealChanges, AreNeverNumericalNoise) {
  const RealChange& param = GetParam();
  int reached = 0;
  for (const std::string& golden : param.goldens) {
    const CheckOutcome outcome =
        param.scene_file.empty()
            ? testing::check_golden_variant(golden, param.change)
            : check_scene_file_variant(param.scene_file, golden, param.change);
    std::cout << param.name << ": " << outcome.message() << "\n";
    const bool physics_changed = outcome.check.expected_state_hash &&
                                 *outcome.check.expected_state_hash != outcome.check.actual_state_hash;
    if (!physics_changed) continue;
    ++reached;
    EXPECT_TRUE(outcome.failure_class == FailureClass::BehaviourChanged ||
                outcome.failure_class == FailureClass::CannotTell)
        << outcome.message();
    EXPECT_EQ(outcome.message().find("review the images and promote"), std::string::npos)
        << outcome.message();
  }
  if (param.scene_file.empty()) {
    EXPECT_GT(reached, 0) << param.name << " changed the physics of none of its goldens";
  }
}

/// The friction mixing rule changed to another (as a changed default would change it).
void other_friction_mixing(demos::Scene& scene) {
  scene.settings.friction_mixing = scene.settings.friction_mixing == FrictionMixing::Average
                                       ? FrictionMixing::GeometricMean
                                       : FrictionMixing::Average;
}

INSTANTIATE_TEST_SUITE_P(
    Golden, RealChanges,
    ::testing::Values(
        RealChange{"friction_mixing_rule", {"ball_pit/motion", "ball_pit/settled"},
                   other_friction_mixing, ""},
        RealChange{"restitution_threshold_minus_10_percent",
                   {"random_polygons/motion", "random_polygons/settled"},
                   [](demos::Scene& scene) { scene.settings.restitution_threshold *= 0.9f; }, ""},
        // The example project's cannonball (the case) is checked too, but slop +5 %
        // set in its scene settings leaves its state hash unchanged on this build (its
        // contacts never wait on the slop), so the built-in scenes that use slop carry it.
        RealChange{"slop_plus_5_percent_cannonball",
                   {"cannonball/flight", "cannonball/impact", "cannonball/rest"},
                   [](demos::Scene& scene) { scene.settings.slop *= 1.05f; },
                   IMPULSE2D_EXAMPLE_PROJECT "/scenes/cannonball.json"},
        RealChange{"slop_plus_5_percent",
                   {"tutorial/settled", "pyramid/settled", "stack/settled", "ball_pit/settled"},
                   [](demos::Scene& scene) { scene.settings.slop *= 1.05f; }, ""}),
    [](const ::testing::TestParamInfo<RealChange>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace impulse2d::golden

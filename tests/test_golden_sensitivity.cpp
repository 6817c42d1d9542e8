/// @file test_golden_sensitivity.cpp
/// The suite catches what matters: a scene run with one small physics change (a mixing rule
/// swapped, a coefficient or constant off by 5%, one solver iteration fewer) fails against
/// the committed golden as *behaviour changed* (it leaves the golden's noise envelope),
/// naming what left it and the bodies that moved; the unchanged run passes. Variants never write goldens or artifacts.
#include <gtest/gtest.h>

#include <iostream>
#include <ostream>
#include <string>

#include "core/world.h"
#include "scene/scene.h"
#include "tests/test_golden_support.h"
#include "tools/golden_scenes/golden_catalog.h"
#include "tools/golden_scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

/// The golden most variants run against: the tutorial's scene uses every method choice the
/// variants change (its own mixing rules, linear projection, bouncy and frictional bodies).
constexpr const char* kGolden = "tutorial/motion";

/// A named small change to a scene, checked against golden `golden`.
struct Variant {
  std::string name;
  SceneVariant change;
  std::string golden = kGolden;
};

/// Every body's static and dynamic friction coefficients scaled by `factor` once the scene is
/// built (for scenes whose bodies all come from `build`).
SceneVariant scale_friction(float factor) {
  return [factor](demos::Scene& scene) {
    scene.build = [build = scene.build, factor](World& world, const demos::Params& params) {
      build(world, params);
      for (const BodyId id : world.body_ids()) {
        Material material = world.body(id).material;
        material.static_friction *= factor;
        material.dynamic_friction *= factor;
        world.set_material(id, material);
      }
    };
  };
}

/// Prints a variant as its name (GoogleTest would dump its bytes).
void PrintTo(const Variant& variant, std::ostream* out) { *out << variant.name; }

CheckSettings read_only_settings() {
  CheckSettings settings = testing::suite_settings();
  settings.update_mode = UpdateMode::None;
  settings.artifact_root.clear();
  return settings;
}

CheckOutcome check_variant(const SceneVariant& change, const std::string& golden = kGolden) {
  const GoldenSpec* spec = find_golden(golden);
  if (spec == nullptr) throw std::logic_error("no golden " + golden);
  return run_golden_check(spec->id(), spec->scene, static_cast<int>(spec->step),
                          scene_frame_producer(*spec, change), read_only_settings());
}

class GoldenSensitivity : public ::testing::TestWithParam<Variant> {};

TEST_P(GoldenSensitivity, FailsAsBehaviourChanged) {
  const CheckOutcome outcome = check_variant(GetParam().change, GetParam().golden);
  std::cout << GetParam().name << ": " << outcome.message() << "\n";
  EXPECT_EQ(outcome.failure_class, FailureClass::BehaviourChanged) << outcome.message();
  ASSERT_TRUE(outcome.check.noise.has_value()) << outcome.message();
  EXPECT_FALSE(outcome.check.noise->escapes.empty()) << outcome.message();
  EXPECT_FALSE(outcome.check.moved_bodies.empty()) << outcome.message();
  EXPECT_FALSE(outcome.golden_written);
}

INSTANTIATE_TEST_SUITE_P(
    Golden, GoldenSensitivity,
    ::testing::Values(
        Variant{"friction_mixing_geometric_mean",
                [](demos::Scene& scene) {
                  ASSERT_EQ(scene.settings.friction_mixing, FrictionMixing::RootSumSquares);
                  scene.settings.friction_mixing = FrictionMixing::GeometricMean;
                }},
        Variant{"restitution_mixing_maximum",
                [](demos::Scene& scene) {
                  ASSERT_EQ(scene.settings.restitution_mixing, RestitutionMixing::Minimum);
                  scene.settings.restitution_mixing = RestitutionMixing::Maximum;
                }},
        Variant{"correction_percent_plus_5_percent",
                [](demos::Scene& scene) { scene.settings.correction_percent *= 1.05f; }},
        Variant{"gravity_plus_5_percent",
                [](demos::Scene& scene) { scene.settings.gravity.y *= 1.05f; }},
        Variant{"one_velocity_iteration_fewer",
                [](demos::Scene& scene) { scene.model.velocity_iterations -= 1; }},
        Variant{"friction_coefficients_plus_5_percent", scale_friction(1.05f),
                "friction_ramp/motion"}),
    [](const ::testing::TestParamInfo<Variant>& param_info) { return param_info.param.name; });

TEST(GoldenSensitivity, UnchangedRunPasses) {
  const CheckOutcome outcome = check_variant(nullptr);
  EXPECT_EQ(outcome.failure_class, FailureClass::None) << outcome.message();
  // The friction variant's wrapper itself changes nothing when the factor is 1.
  const CheckOutcome ramp = check_variant(scale_friction(1.0f), "friction_ramp/motion");
  EXPECT_EQ(ramp.failure_class, FailureClass::None) << ramp.message();
}

}  // namespace
}  // namespace impulse2d::golden

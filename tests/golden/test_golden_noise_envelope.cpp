/// @file test_golden_noise_envelope.cpp
/// The noise envelope on synthetic data: checkpoint steps, the judgement (inside, beyond
/// the margin, bodies and samples missing on one side), the JSON form and its errors, and
/// the check runner calling the measurer only when it writes a sidecar, then classing a
/// small drift as numerical noise and a large one as behaviour changed.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "tests/golden/test_golden_temp_dir.h"
#include "golden/check_run.h"
#include "golden/error.h"
#include "golden/noise_envelope.h"

namespace impulse2d::golden {
namespace {

using nlohmann::json;

/// One body "ball" at (1, 2), noise 0.1 m / 0.01 rad; one checkpoint at step 10.
NoiseEnvelope small_envelope() {
  NoiseEnvelope envelope;
  envelope.perturbations = {"time_step +1 ulp"};
  NoiseCheckpoint checkpoint;
  checkpoint.golden = {10, 50.0, 1.0, -2.0, 0.5, 3};
  checkpoint.spread = {10, 0.5, 0.01, 0.01, 0.01, 1};
  envelope.checkpoints = {checkpoint};
  envelope.bodies = {{"ball", 0.1, 0.01}};
  return envelope;
}

const std::vector<BodyPose> kGoldenBodies = {{"ball", 1.0, 2.0, 0.0}};

TEST(NoiseEnvelope, CheckpointStepsSpreadOverTheRunAndEndAtTheFrame) {
  EXPECT_TRUE(noise_checkpoint_steps(0).empty());
  EXPECT_EQ(noise_checkpoint_steps(3), (std::vector<std::int64_t>{1, 2, 3}));
  const std::vector<std::int64_t> steps = noise_checkpoint_steps(900);
  ASSERT_EQ(steps.size(), 32u);
  EXPECT_EQ(steps.back(), 900);
  for (std::size_t i = 1; i < steps.size(); ++i) EXPECT_LT(steps[i - 1], steps[i]);
}

TEST(NoiseEnvelope, InsideTheMarginIsNoiseBeyondItNamesWhatLeft) {
  const NoiseEnvelope envelope = small_envelope();
  // Twice the noise is still noise (kNoiseMargin), a little more is not.
  const NoiseVerdict inside = judge_against_envelope(
      envelope, kGoldenBodies, {{"ball", 1.19, 2.0, 0.019}}, {{10, 50.9, 1.0, -2.0, 0.5, 5}});
  EXPECT_TRUE(inside.within()) << inside.describe(5);
  EXPECT_EQ(inside.compared, 7u);
  EXPECT_NE(inside.describe(5).find("7 compared"), std::string::npos);

  const NoiseVerdict outside = judge_against_envelope(
      envelope, kGoldenBodies, {{"ball", 1.3, 2.0, 0.0}}, {{10, 50.0, 1.0, -2.0, 0.9, 3}});
  ASSERT_EQ(outside.escapes.size(), 2u) << outside.describe(5);
  // Worst first: angular momentum is 40x its noise, the ball 3x.
  EXPECT_EQ(outside.escapes[0].what, "angular momentum at step 10");
  EXPECT_EQ(outside.escapes[1].what, "ball position");
  EXPECT_NE(outside.describe(5).find("2. ball position off by 0.3 m (noise envelope 0.1 m, limit 0.2)"),
            std::string::npos)
      << outside.describe(5);
  // Only the `count` largest are named, then how many more.
  EXPECT_NE(outside.describe(1).find("(1 more outside the envelope: 1 body, 0 quantities)"),
            std::string::npos)
      << outside.describe(1);
}

TEST(NoiseEnvelope, ZeroEnvelopeTriviaRanksBelowLargeEscapes) {
  // Issue 29: "momentum x off by 4.23e-11 (envelope 0)" was listed before "angular momentum
  // off by 4.65"; sizes are relative to max(envelope, 1e-6 x (1 + |value|)).
  NoiseEnvelope envelope = small_envelope();
  envelope.checkpoints[0].spread.momentum_x = 0.0;
  const NoiseVerdict verdict = judge_against_envelope(
      envelope, kGoldenBodies, kGoldenBodies, {{10, 50.0, 1.0 + 4.23e-11, -2.0, 5.15, 3}});
  ASSERT_EQ(verdict.escapes.size(), 2u) << verdict.describe(5);
  EXPECT_EQ(verdict.escapes[0].what, "angular momentum at step 10");
  EXPECT_EQ(verdict.escapes[1].what, "momentum x at step 10");
}

TEST(NoiseEnvelope, InsideALargeEnvelopeIsCannotTellNamingTheStepItStopsTelling) {
  // One ball, scene size 1 m: the bound is 1 cm. The envelope lets it move 0.2 m.
  NoiseEnvelope envelope = small_envelope();
  NoiseCheckpoint early = envelope.checkpoints[0];
  early.golden.step = 5;
  early.spread.step = 5;
  early.body_spread = 0.001;
  envelope.checkpoints[0].body_spread = 0.1;
  envelope.checkpoints.insert(envelope.checkpoints.begin(), early);
  const NoiseVerdict verdict = judge_against_envelope(
      envelope, kGoldenBodies, {{"ball", 1.15, 2.0, 0.0}},
      {{5, 50.0, 1.0, -2.0, 0.5, 3}, {10, 50.0, 1.0, -2.0, 0.5, 3}});
  EXPECT_TRUE(verdict.within()) << verdict.describe(5);
  EXPECT_TRUE(verdict.cannot_tell());
  EXPECT_DOUBLE_EQ(verdict.bound, 0.01);
  EXPECT_EQ(verdict.stops_telling_step, 10);
  EXPECT_EQ(verdict.last_telling_step, 5);
  const std::string text = verdict.describe_cannot_tell();
  EXPECT_NE(text.find("from step 10, and a frame at step 5 or earlier still tells"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("the bound within which a change is called noise is 0.01 m"), std::string::npos) << text;

  // A move within the bound, inside an envelope within it too, is noise.
  envelope.bodies[0].distance = 0.004;
  for (NoiseCheckpoint& checkpoint : envelope.checkpoints) checkpoint.body_spread = 0.004;
  const NoiseVerdict small = judge_against_envelope(
      envelope, kGoldenBodies, {{"ball", 1.005, 2.0, 0.0}},
      {{5, 50.0, 1.0, -2.0, 0.5, 3}, {10, 50.0, 1.0, -2.0, 0.5, 3}});
  EXPECT_TRUE(small.within()) << small.describe(5);
  EXPECT_FALSE(small.cannot_tell());
}

TEST(NoiseEnvelope, TheLivingSetIsPartOfTheEnvelope) {
  // A body some perturbed run had removed may be missing; one some run kept may be extra.
  NoiseEnvelope envelope = small_envelope();
  envelope.bodies[0].may_be_missing = true;
  envelope.extra_bodies = {"body #7"};
  envelope.checkpoints[0].golden.bodies = 4;
  envelope.checkpoints[0].spread.bodies = 1;
  const NoiseVerdict verdict = judge_against_envelope(
      envelope, kGoldenBodies, {{"body #7", 5.0, 5.0, 0.0}}, {{10, 50.0, 1.0, -2.0, 0.5, 3, 5}});
  EXPECT_TRUE(verdict.within()) << verdict.describe(5);
  const NoiseVerdict two_more = judge_against_envelope(
      envelope, kGoldenBodies, kGoldenBodies, {{10, 50.0, 1.0, -2.0, 0.5, 3, 7}});
  ASSERT_FALSE(two_more.within());
  EXPECT_EQ(two_more.escapes[0].what, "living bodies at step 10");
  // Rounding already changes which bodies live at the frame: another body alive (or gone) is
  // not told from rounding by eight samples, so it is "cannot tell", never noise.
  const NoiseVerdict stranger = judge_against_envelope(
      envelope, kGoldenBodies, {{"body #8", 5.0, 5.0, 0.0}}, {{10, 50.0, 1.0, -2.0, 0.5, 3, 4}});
  EXPECT_TRUE(stranger.within()) << stranger.describe(5);
  EXPECT_TRUE(stranger.cannot_tell());
  ASSERT_EQ(stranger.unsampled_living_set.size(), 1u);
  EXPECT_EQ(stranger.unsampled_living_set[0], "body #8 (alive in this run only)");
  EXPECT_NE(stranger.describe_cannot_tell().find("which bodies are alive differs (body #8"),
            std::string::npos)
      << stranger.describe_cannot_tell();
  // Where rounding never changes the living set, a body on one side only is a behaviour change.
  NoiseEnvelope steady = small_envelope();
  const NoiseVerdict extra = judge_against_envelope(
      steady, kGoldenBodies, {{"ball", 1.0, 2.0, 0.0}, {"body #8", 5.0, 5.0, 0.0}},
      {{10, 50.0, 1.0, -2.0, 0.5, 3}});
  ASSERT_FALSE(extra.within());
  EXPECT_NE(extra.describe(5).find("body #8 (not in the golden run)"), std::string::npos);
  const NoiseVerdict gone = judge_against_envelope(steady, kGoldenBodies, {}, {{10, 50.0, 1.0, -2.0, 0.5, 3}});
  ASSERT_FALSE(gone.within());
  EXPECT_NE(gone.describe(5).find("ball (missing in this run)"), std::string::npos);

  const NoiseEnvelope back =
      noise_envelope_from_json(noise_envelope_to_json(envelope), "sidecar 'a.json'");
  EXPECT_TRUE(back.bodies[0].may_be_missing);
  EXPECT_EQ(back.extra_bodies, envelope.extra_bodies);
  EXPECT_EQ(back.checkpoints[0].golden.bodies, 4);
  EXPECT_EQ(back.checkpoints[0].spread.bodies, 1);
}

TEST(NoiseEnvelope, AZeroEnvelopeAllowsNoChangeAndMissingDataEscapes) {
  NoiseEnvelope envelope = small_envelope();
  envelope.bodies[0].distance = 0.0;
  const NoiseVerdict same = judge_against_envelope(envelope, kGoldenBodies, kGoldenBodies,
                                                   {envelope.checkpoints[0].golden});
  EXPECT_TRUE(same.within()) << same.describe(5);
  const NoiseVerdict moved = judge_against_envelope(envelope, kGoldenBodies,
                                                    {{"ball", 1.0, 2.000001, 0.0}},
                                                    {envelope.checkpoints[0].golden});
  EXPECT_FALSE(moved.within());

  const NoiseVerdict renamed =
      judge_against_envelope(envelope, kGoldenBodies, {{"box", 1.0, 2.0, 0.0}}, {});
  std::string text = renamed.describe(5);
  EXPECT_NE(text.find("ball (missing in this run)"), std::string::npos) << text;
  EXPECT_NE(text.find("box (not in the golden run)"), std::string::npos) << text;
  EXPECT_NE(text.find("physics sample at step 10 (not taken in this run)"), std::string::npos)
      << text;
}

TEST(NoiseEnvelope, JsonRoundTripsAndBadFieldsAreNamed) {
  const NoiseEnvelope envelope = small_envelope();
  const json object = noise_envelope_to_json(envelope);
  const NoiseEnvelope back = noise_envelope_from_json(object, "sidecar 'a.json'");
  EXPECT_EQ(back.perturbations, envelope.perturbations);
  ASSERT_EQ(back.checkpoints.size(), 1u);
  EXPECT_EQ(back.checkpoints[0].golden.contacts, 3);
  EXPECT_EQ(back.checkpoints[0].spread.angular_momentum, 0.01);
  ASSERT_EQ(back.bodies.size(), 1u);
  EXPECT_EQ(back.bodies[0].name, "ball");

  const auto error_of = [&](const std::function<void(json&)>& change) {
    json bad = object;
    change(bad);
    try {
      noise_envelope_from_json(bad, "sidecar 'a.json'");
    } catch (const GoldenError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of([](json& j) { j["checkpoints"][0]["energy_noise"] = -1.0; })
                .find("sidecar 'a.json': field 'noise.checkpoints[0].energy_noise': must be >= 0"),
            std::string::npos);
  EXPECT_NE(error_of([](json& j) { j["checkpoints"].push_back(j["checkpoints"][0]); })
                .find("field 'noise.checkpoints[1].step': checkpoints must be in ascending"),
            std::string::npos);
  EXPECT_NE(error_of([](json& j) { j["bodies"][0]["speed"] = 1.0; })
                .find("field 'noise.bodies[0].speed': unknown field"),
            std::string::npos);
  EXPECT_NE(error_of([](json& j) { j["perturbations"] = json::array(); })
                .find("field 'noise.perturbations': must name at least one"),
            std::string::npos);
}

/// A frame of one body "ball" at x = `x`: hash and pixels follow x.
ProducedFrame ball_frame(double x) {
  ProducedFrame frame;
  frame.image = image::make_image(8, 8, image::Rgba{200, 200, 200, 255});
  frame.image.set_pixel(static_cast<int>(x * 2.0) % 8, 4, image::Rgba{0, 0, 0, 255});
  frame.state_hash = static_cast<std::uint64_t>(x * 1000.0);
  // A ground 40 m away gives the scene its size: noise is bounded by 1 % of it (0.4 m).
  frame.bodies = {{"ball", x, 2.0, 0.0}, {"ground", 41.0, 2.0, 0.0}};
  frame.samples = {{10, 50.0, 1.0, -2.0, 0.5, 3}};
  return frame;
}

TEST(NoiseEnvelope, CheckRunMeasuresOnlyWhenWritingAndClassesByTheEnvelope) {
  const testing::TempDir temp;
  CheckSettings settings;
  settings.golden_dir = temp.path() / "golden_images";
  int measured = 0;
  const NoiseMeasurer measure = [&measured] {
    ++measured;
    return small_envelope();
  };
  auto check = [&](double x, UpdateMode mode) {
    settings.update_mode = mode;
    return run_golden_check("balls/one", "balls", 10, [x] { return ball_frame(x); }, settings,
                            measure);
  };
  ASSERT_TRUE(check(1.0, UpdateMode::Missing).golden_written);
  EXPECT_EQ(measured, 1);
  EXPECT_EQ(read_sidecar(sidecar_path_for(golden_png_path(settings.golden_dir, "balls/one")))
                .noise.bodies.size(),
            1u);
  EXPECT_EQ(check(1.0, UpdateMode::None).failure_class, FailureClass::None);
  const CheckOutcome noise = check(1.05, UpdateMode::None);
  EXPECT_EQ(noise.failure_class, FailureClass::NumericalNoise) << noise.message();
  EXPECT_NE(noise.message().find("numerical noise"), std::string::npos);
  const CheckOutcome changed = check(1.5, UpdateMode::None);
  EXPECT_EQ(changed.failure_class, FailureClass::BehaviourChanged) << changed.message();
  EXPECT_NE(changed.message().find("ball position off by 0.5 m"), std::string::npos)
      << changed.message();
  EXPECT_EQ(measured, 1) << "checks that write no sidecar must not measure";
}

}  // namespace
}  // namespace impulse2d::golden

/// @file test_golden_check_run.cpp
/// The check runner on synthetic frame producers: a missing golden fails and leaves a
/// promotable actual, update modes write goldens, each failure class is told apart, a
/// nondeterministic frame is never written, stale artifacts leave the report once a golden
/// passes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/golden/test_golden_environment.h"
#include "tests/golden/test_golden_temp_dir.h"
#include "golden/check_run.h"
#include "image/file_io.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using testing::ScopedEnvironment;
using testing::TempDir;

constexpr const char* kName = "boxes/settled";

/// A 16x12 frame: grey background, `body_x` marks a red column; hash and poses follow it.
ProducedFrame synthetic_frame(int body_x, std::uint64_t state_hash) {
  ProducedFrame frame;
  frame.image = image::make_image(16, 12, image::Rgba{200, 200, 200, 255});
  for (int y = 2; y < 10; ++y) frame.image.set_pixel(body_x, y, image::Rgba{220, 30, 30, 255});
  frame.state_hash = state_hash;
  frame.bodies = {{"body 0", 0.0, 0.0, 0.0}, {"body 1", 0.1 * body_x, 1.0, 0.0}};
  frame.renderer = {"llvmpipe (test)", "4.5 test"};
  return frame;
}

FrameProducer fixed(int body_x, std::uint64_t state_hash) {
  return [=] { return synthetic_frame(body_x, state_hash); };
}

class GoldenCheckRun : public ::testing::Test {
 protected:
  CheckSettings settings(UpdateMode mode) const {
    CheckSettings result;
    result.golden_dir = temp_.path() / "golden_images";
    result.artifact_root = temp_.path() / "artifacts";
    result.update_mode = mode;
    return result;
  }
  CheckOutcome check(const FrameProducer& producer, UpdateMode mode = UpdateMode::None) const {
    return run_golden_check(kName, "boxes", 30, producer, settings(mode));
  }
  /// Writes the golden of `fixed(body_x, state_hash)` through the runner itself.
  void bless(int body_x, std::uint64_t state_hash) const {
    ASSERT_TRUE(check(fixed(body_x, state_hash), UpdateMode::All).golden_written);
  }
  fs::path failure_dir() const { return temp_.path() / "artifacts" / kName; }
  fs::path golden_png() const { return golden_png_path(temp_.path() / "golden_images", kName); }
  nlohmann::json metrics() const {
    return nlohmann::json::parse(image::read_text_file(failure_dir() / "metrics.json"));
  }

  TempDir temp_;
};

TEST_F(GoldenCheckRun, MissingGoldenFailsAndLeavesAPromotableActual) {
  const CheckOutcome outcome = check(fixed(5, 1));
  EXPECT_EQ(outcome.failure_class, FailureClass::MissingGolden);
  EXPECT_FALSE(outcome.passed());
  EXPECT_FALSE(fs::exists(golden_png()));
  EXPECT_TRUE(fs::exists(failure_dir() / "actual.png"));
  const Sidecar sidecar = read_sidecar(failure_dir() / "actual.json");
  EXPECT_EQ(sidecar.scene, "boxes");
  EXPECT_EQ(sidecar.frame, 30);
  EXPECT_EQ(sidecar.state_hash, 1u);
  EXPECT_EQ(sidecar.bodies.size(), 2u);
  EXPECT_EQ(outcome.report, temp_.path() / "artifacts" / "index.html");
  EXPECT_TRUE(fs::exists(outcome.report));
  EXPECT_NE(outcome.message().find("golden 'boxes/settled': missing golden: "), std::string::npos)
      << outcome.message();
  EXPECT_NE(outcome.message().find("report: "), std::string::npos);
}

TEST_F(GoldenCheckRun, MissingModeWritesTheGoldenAndAPassClearsStaleArtifacts) {
  ASSERT_FALSE(check(fixed(5, 1)).passed());
  ASSERT_TRUE(fs::exists(failure_dir() / "metrics.json"));

  const CheckOutcome written = check(fixed(5, 1), UpdateMode::Missing);
  EXPECT_TRUE(written.golden_written);
  EXPECT_TRUE(written.passed()) << written.message();
  EXPECT_TRUE(fs::exists(golden_png()));
  EXPECT_TRUE(fs::exists(sidecar_path_for(golden_png())));

  const CheckOutcome again = check(fixed(5, 1));
  EXPECT_EQ(again.failure_class, FailureClass::None) << again.message();
  EXPECT_FALSE(again.golden_written);
  EXPECT_FALSE(fs::exists(failure_dir().parent_path()))
      << "the stale failure must leave the report";
  const std::string report = image::read_text_file(temp_.path() / "artifacts" / "index.html");
  EXPECT_NE(report.find("0 failures"), std::string::npos);
}

TEST_F(GoldenCheckRun, MissingModeDoesNotRewriteAChangedGolden) {
  bless(5, 1);
  const CheckOutcome outcome = check(fixed(6, 2), UpdateMode::Missing);
  EXPECT_EQ(outcome.failure_class, FailureClass::SimulationDiverged);
  EXPECT_FALSE(outcome.golden_written);
  EXPECT_EQ(read_sidecar(sidecar_path_for(golden_png())).state_hash, 1u);
}

TEST_F(GoldenCheckRun, ChangedModeRewritesAFailingGolden) {
  bless(5, 1);
  const CheckOutcome outcome = check(fixed(6, 2), UpdateMode::Changed);
  EXPECT_TRUE(outcome.golden_written);
  EXPECT_EQ(read_sidecar(sidecar_path_for(golden_png())).state_hash, 2u);
  EXPECT_EQ(check(fixed(6, 2)).failure_class, FailureClass::None);
}

TEST_F(GoldenCheckRun, StateHashChangeIsSimulationDivergedNamingTheMovedBody) {
  bless(5, 1);
  const CheckOutcome outcome = check(fixed(8, 2));
  EXPECT_EQ(outcome.failure_class, FailureClass::SimulationDiverged);
  ASSERT_EQ(outcome.check.moved_bodies.size(), 1u);
  EXPECT_EQ(outcome.check.moved_bodies[0].name, "body 1");
  EXPECT_NE(outcome.message().find("body 1 moved 0.3"), std::string::npos) << outcome.message();
  for (const char* file :
       {"actual.png", "actual.json", "expected.png", "diff.png", "heatmap.png", "metrics.json"}) {
    EXPECT_TRUE(fs::exists(failure_dir() / file)) << file;
  }
  EXPECT_EQ(metrics()["class"], "simulation_diverged");
}

TEST_F(GoldenCheckRun, InvisibleStateChangeStillFails) {
  bless(5, 1);
  const CheckOutcome outcome = check(fixed(5, 2));
  EXPECT_EQ(outcome.failure_class, FailureClass::SimulationDiverged) << outcome.message();
}

TEST_F(GoldenCheckRun, SameStateDifferentPixelsIsRasterisation) {
  bless(5, 1);
  const CheckOutcome outcome = check([] {
    ProducedFrame frame = synthetic_frame(5, 1);
    frame.image.set_pixel(0, 0, image::Rgba{0, 0, 0, 255});
    return frame;
  });
  EXPECT_EQ(outcome.failure_class, FailureClass::RasterisationDiffers) << outcome.message();
  EXPECT_NE(outcome.message().find("physics state matches"), std::string::npos);
}

TEST_F(GoldenCheckRun, SidecarToleranceIsAppliedAndNamed) {
  bless(5, 1);
  Sidecar sidecar = read_sidecar(sidecar_path_for(golden_png()));
  sidecar.tolerance.max_channel_delta = 2;
  sidecar.tolerance.max_differing_pixels = 1;
  sidecar.tolerance.max_differing_ratio = 0.01;
  sidecar.tolerance.max_window_pixels = 1;
  write_sidecar(sidecar_path_for(golden_png()), sidecar);

  const CheckOutcome slight = check([] {
    ProducedFrame frame = synthetic_frame(5, 1);
    frame.image.set_pixel(0, 0, image::Rgba{201, 200, 200, 255});
    return frame;
  });
  EXPECT_EQ(slight.failure_class, FailureClass::None) << slight.message();

  const CheckOutcome cluster = check([] {
    ProducedFrame frame = synthetic_frame(5, 1);
    for (int y = 0; y < 3; ++y) frame.image.set_pixel(0, y, image::Rgba{0, 0, 0, 255});
    return frame;
  });
  EXPECT_EQ(cluster.failure_class, FailureClass::RasterisationDiffers);
  EXPECT_NE(cluster.message().find("override from sidecar 'boxes/settled.json'"), std::string::npos)
      << cluster.message();
}

TEST_F(GoldenCheckRun, NondeterministicFrameIsNeverWrittenNorPromotable) {
  int calls = 0;
  const FrameProducer flaky = [&calls] { return synthetic_frame(5 + calls++, 1); };
  const CheckOutcome outcome = check(flaky, UpdateMode::All);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(outcome.failure_class, FailureClass::Nondeterminism);
  EXPECT_FALSE(outcome.golden_written);
  EXPECT_FALSE(fs::exists(golden_png()));
  EXPECT_TRUE(fs::exists(failure_dir() / "actual.png"));
  EXPECT_FALSE(fs::exists(failure_dir() / "actual.json"));
}

TEST_F(GoldenCheckRun, AMatchRendersOnce) {
  bless(5, 1);
  int calls = 0;
  const CheckOutcome outcome = check([&calls] {
    ++calls;
    return synthetic_frame(5, 1);
  });
  EXPECT_EQ(outcome.failure_class, FailureClass::None);
  EXPECT_EQ(calls, 1);
}

TEST_F(GoldenCheckRun, ImageWithoutSidecarCountsAsMissing) {
  bless(5, 1);
  fs::remove(sidecar_path_for(golden_png()));
  EXPECT_EQ(check(fixed(5, 1)).failure_class, FailureClass::MissingGolden);
}

TEST_F(GoldenCheckRun, NoArtifactRootWritesNoArtifacts) {
  CheckSettings quiet = settings(UpdateMode::None);
  quiet.artifact_root.clear();
  const CheckOutcome outcome = run_golden_check(kName, "boxes", 30, fixed(5, 1), quiet);
  EXPECT_EQ(outcome.failure_class, FailureClass::MissingGolden);
  EXPECT_TRUE(outcome.artifact_dir.empty());
  EXPECT_FALSE(fs::exists(temp_.path() / "artifacts"));
}

TEST(GoldenCheckSettings, EnvironmentOverridesDirectoriesAndCiForcesNone) {
  ScopedEnvironment environment;
  environment.set("GOLDEN_IMAGES_DIR", "/tmp/goldens-here");
  environment.set("GOLDEN_ARTIFACT_DIR", "/tmp/artifacts-here");
  environment.set("GOLDEN_UPDATE", "all");
  environment.set("CI", "true");
  const CheckSettings settings = check_settings_from_environment("/src/golden", "/build/art");
  EXPECT_EQ(settings.golden_dir, "/tmp/goldens-here");
  EXPECT_EQ(settings.artifact_root, "/tmp/artifacts-here");
  EXPECT_EQ(settings.update_mode, UpdateMode::None);

  for (const char* name : {"GOLDEN_IMAGES_DIR", "GOLDEN_ARTIFACT_DIR", "GOLDEN_UPDATE", "CI"}) {
    environment.set(name, nullptr);
  }
  const CheckSettings defaults = check_settings_from_environment("/src/golden", "/build/art");
  EXPECT_EQ(defaults.golden_dir, "/src/golden");
  EXPECT_EQ(defaults.artifact_root, "/build/art");
  EXPECT_EQ(defaults.update_mode, UpdateMode::None);
}

}  // namespace
}  // namespace impulse2d::golden

/// @file test_golden_scenes.cpp
/// One test per golden image: the built-in scene simulated to the golden's step, rendered,
/// and compared (exact first, then the sidecar's tolerance). A failure is classified (a
/// physics change against the sidecar's noise envelope); its artifacts land under
/// GOLDEN_ARTIFACT_DIR with the HTML report. GOLDEN_UPDATE writes goldens (never under CI),
/// each only after a child process rendered the same frame; GOLDEN_REPEAT=2 makes every
/// check compare with a child process.
#include <gtest/gtest.h>

#include <iostream>
#include <ostream>

#include "tests/golden/test_golden_child.h"
#include "tests/golden/test_golden_support.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/noise_probe.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden {

/// Prints a golden parameter as its id (GoogleTest would dump its bytes).
void PrintTo(const GoldenSpec& spec, std::ostream* out) { *out << spec.id(); }

namespace {

class GoldenScenes : public ::testing::TestWithParam<GoldenSpec> {};

TEST_P(GoldenScenes, MatchesGolden) {
  const GoldenSpec& spec = GetParam();
  const CheckOutcome outcome =
      run_golden_check(spec.id(), spec.scene, static_cast<int>(spec.step),
                       scene_frame_producer(spec), testing::suite_settings(),
                       scene_noise_measurer(spec), testing::child_process_producer(spec.id()));
  if (outcome.golden_written) std::cout << outcome.message() << "\n";
  if (outcome.failure_class == FailureClass::NoRendererBaseline) GTEST_SKIP() << outcome.message();
  EXPECT_TRUE(outcome.passed()) << outcome.message();
}

INSTANTIATE_TEST_SUITE_P(Golden, GoldenScenes, ::testing::ValuesIn(golden_catalog()),
                         [](const ::testing::TestParamInfo<GoldenSpec>& param_info) {
                           return golden_test_name(param_info.param);
                         });

}  // namespace
}  // namespace impulse2d::golden

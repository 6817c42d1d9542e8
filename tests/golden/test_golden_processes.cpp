/// @file test_golden_processes.cpp
/// Nondeterminism across processes is its own class: a frame whose physics depends on the
/// process (here gravity derived from the pid, as a value derived from an address under ASLR
/// would be) agrees with itself inside one process, so only a second process shows it. An
/// update compares with a child process before writing and refuses; a check with repeat 2
/// fails as *nondeterministic*, never *rasterisation differs* or a physics class.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/golden/test_golden_child.h"
#include "tests/golden/test_golden_support.h"
#include "tests/golden/test_golden_temp_dir.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;

constexpr const char* kGolden = "tutorial/motion";

const GoldenSpec& spec() {
  const GoldenSpec* found = find_golden(kGolden);
  if (found == nullptr) throw std::logic_error("no golden tutorial/motion");
  return *found;
}

CheckOutcome check(const CheckSettings& settings, testing::ChildVariant variant) {
  return run_golden_check(
      kGolden, spec().scene, static_cast<int>(spec().step),
      scene_frame_producer(spec(), testing::child_variant(variant)), settings, nullptr,
      testing::child_process_producer(kGolden, {}, variant));
}

TEST(GoldenProcesses, UpdateRefusesAFrameThatDiffersBetweenProcesses) {
  const testing::TempDir temp;
  CheckSettings settings;
  settings.golden_dir = temp.path() / "golden_images";
  settings.update_mode = UpdateMode::All;
  const CheckOutcome outcome = check(settings, testing::ChildVariant::ProcessDependentGravity);
  EXPECT_EQ(outcome.failure_class, FailureClass::Nondeterminism) << outcome.message();
  EXPECT_TRUE(outcome.check.second_render_identical) << "one process agrees with itself";
  EXPECT_FALSE(outcome.check.other_process_identical);
  EXPECT_FALSE(outcome.golden_written);
  EXPECT_FALSE(fs::exists(golden_png_path(settings.golden_dir, kGolden)));
  EXPECT_NE(outcome.message().find("two separate processes"), std::string::npos)
      << outcome.message();

  // The same update of the deterministic scene writes the golden.
  const CheckOutcome written = check(settings, testing::ChildVariant::None);
  EXPECT_TRUE(written.golden_written) << written.message();
}

TEST(GoldenProcesses, RepeatTwoCheckCallsItNondeterministic) {
  CheckSettings settings = testing::suite_settings();
  settings.update_mode = UpdateMode::None;
  settings.artifact_root.clear();
  settings.repeat = 2;
  const CheckOutcome outcome = check(settings, testing::ChildVariant::ProcessDependentGravity);
  EXPECT_EQ(outcome.failure_class, FailureClass::Nondeterminism) << outcome.message();
  EXPECT_FALSE(outcome.check.other_process_identical);

  const CheckOutcome steady = check(settings, testing::ChildVariant::None);
  EXPECT_TRUE(testing::passes_on_this_renderer(steady)) << steady.message();
  EXPECT_TRUE(steady.check.other_process_identical);
}

}  // namespace
}  // namespace impulse2d::golden

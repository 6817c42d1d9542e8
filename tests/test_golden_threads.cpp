/// @file test_golden_threads.cpp
/// The suite is insensitive to what does not matter: goldens rendered with LP_NUM_THREADS=1
/// and =2 match the committed golden exactly, state hash included. llvmpipe reads the
/// variable once per process, so each setting runs in a child process (this binary).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/test_golden_support.h"
#include "tests/test_render_support.h"
#include "tools/golden/compare.h"
#include "tools/golden/file_io.h"
#include "tools/golden/hex_hash.h"
#include "tools/golden/sidecar.h"
#include "tools/golden_scenes/golden_catalog.h"
#include "tools/golden_scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;

constexpr const char* kGoldenVariable = "IMPULSE2D_GOLDEN_CHILD_GOLDEN";
constexpr const char* kOutputVariable = "IMPULSE2D_GOLDEN_CHILD_OUTPUT";

/// Goldens with many overlapping primitives and every overlay kind between them.
constexpr const char* kGoldens[] = {"ball_pit/motion_overlays", "shape_pairs/motion_all_overlays"};

// Runs only as a child: renders the golden named by IMPULSE2D_GOLDEN_CHILD_GOLDEN into the
// PNG named by IMPULSE2D_GOLDEN_CHILD_OUTPUT, and its state hash into "<output>.hash".
TEST(GoldenThreadsChild, WriteFrame) {
  const char* id = std::getenv(kGoldenVariable);
  const char* output = std::getenv(kOutputVariable);
  if (id == nullptr || output == nullptr) GTEST_SKIP() << "runs only as a child of GoldenThreads";
  const GoldenSpec* spec = find_golden(id);
  ASSERT_NE(spec, nullptr) << id;
  const ProducedFrame frame = produce_scene_frame(*spec, shared_golden_renderer());
  save_png(output, frame.image);
  write_text_file_atomically(std::string(output) + ".hash", to_hex_hash(frame.state_hash));
}

TEST(GoldenThreads, OneAndTwoRasteriserThreadsMatchTheGoldenExactly) {
  const fs::path directory = render::testing::make_temporary_directory("golden-threads");
  ASSERT_FALSE(directory.empty());
  for (const char* id : kGoldens) {
    const fs::path golden = golden_png_path(testing::golden_dir(), id);
    ASSERT_TRUE(fs::exists(golden)) << "golden " << id << " is missing";
    const Image expected = load_png(golden);
    const Sidecar sidecar = read_sidecar(sidecar_path_for(golden), std::string(id) + ".json");
    for (const int threads : {1, 2}) {
      const fs::path output = directory / ("threads_" + std::to_string(threads) + ".png");
      const int status = render::testing::run_self("GoldenThreadsChild.WriteFrame",
                                                   {{"LP_NUM_THREADS", std::to_string(threads)},
                                                    {kGoldenVariable, id},
                                                    {kOutputVariable, output.string()}});
      ASSERT_EQ(status, 0) << id << ": child with LP_NUM_THREADS=" << threads << " failed";
      const CompareResult result = compare_images(expected, load_png(output));
      EXPECT_EQ(result.outcome, CompareOutcome::ExactMatch)
          << id << " with LP_NUM_THREADS=" << threads << ": " << result.message();
      EXPECT_EQ(read_text_file(output.string() + ".hash"), to_hex_hash(sidecar.state_hash))
          << id << " with LP_NUM_THREADS=" << threads << ": physics state differs";
    }
  }
  fs::remove_all(directory);
}

}  // namespace
}  // namespace impulse2d::golden

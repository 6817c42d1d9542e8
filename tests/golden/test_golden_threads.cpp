/// @file test_golden_threads.cpp
/// The suite is insensitive to what does not matter: a frame rendered with LP_NUM_THREADS=1
/// and =2 equals the frame rendered in this process, pixels and state hash. llvmpipe reads
/// the variable once per process, so each setting runs in a child process (this binary).
/// Whether the frames match the committed goldens is GoldenScenes' question, not this one:
/// a physics change fails there, not here.
#include <gtest/gtest.h>

#include <string>

#include "tests/golden/test_golden_child.h"
#include "golden/compare.h"
#include "image/hex_hash.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

/// Goldens with many overlapping primitives and every overlay kind between them.
constexpr const char* kGoldens[] = {"ball_pit/motion_overlays", "shape_pairs/motion_all_overlays"};

TEST(GoldenThreads, OneAndTwoRasteriserThreadsDrawTheSameFrame) {
  for (const char* id : kGoldens) {
    const GoldenSpec* spec = find_golden(id);
    ASSERT_NE(spec, nullptr) << id;
    const ProducedFrame here = produce_scene_frame(*spec, shared_golden_renderer());
    for (const int threads : {1, 2}) {
      const ProducedFrame child = testing::child_process_producer(
          id, {{"LP_NUM_THREADS", std::to_string(threads)}})();
      const CompareResult result = compare_images(here.image, child.image);
      EXPECT_EQ(result.outcome, CompareOutcome::ExactMatch)
          << id << ": LP_NUM_THREADS=" << threads
          << " draws another frame than this process: " << result.message();
      EXPECT_EQ(image::to_hex_hash(child.state_hash), image::to_hex_hash(here.state_hash))
          << id << " with LP_NUM_THREADS=" << threads << ": physics state differs between "
          << "processes";
    }
  }
}

}  // namespace
}  // namespace impulse2d::golden

/// @file test_golden_metadata.cpp
/// Every golden frame says what it is: the PNG's tEXt metadata names the scene, step,
/// simulated time, physics state hash, renderer and version, both in a frame as produced and
/// in every committed golden (where it agrees with the sidecar).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "image/png.h"
#include "tests/golden/test_golden_support.h"
#include "image/hex_hash.h"
#include "image/png_text.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden {
namespace {

TEST(GoldenMetadata, ProducedFramesDescribeThemselves) {
  const GoldenSpec* spec = find_golden("shape_pairs/motion");
  ASSERT_NE(spec, nullptr);
  const ProducedFrame frame = produce_scene_frame(*spec, shared_golden_renderer());
  const image::PngText& text = frame.image.text;
  EXPECT_EQ(text.at(image::png_keys::kScene), "shape_pairs");
  EXPECT_EQ(text.at(image::png_keys::kStep), std::to_string(spec->step));
  EXPECT_NEAR(std::stod(text.at(image::png_keys::kTime)), 0.5, 1e-6);  // 30 steps of 1/60 s
  EXPECT_EQ(text.at(image::png_keys::kStateHash), image::to_hex_hash(frame.state_hash));
  EXPECT_EQ(text.at(image::png_keys::kRenderer), frame.renderer.describe());
  EXPECT_EQ(text.at(image::png_keys::kSoftware).rfind("impulse2d ", 0), 0u);
}

TEST(GoldenMetadata, CommittedGoldensAgreeWithTheirSidecars) {
  for (const GoldenSpec& spec : golden_catalog()) {
    const std::filesystem::path png = golden_png_path(testing::golden_dir(), spec.id());
    if (!std::filesystem::exists(png)) continue;  // the golden's own test reports it missing
    const image::Image golden = image::load_png(png);
    const Sidecar sidecar = read_sidecar(sidecar_path_for(png), spec.id() + ".json");
    ASSERT_EQ(golden.text.count(image::png_keys::kStateHash), 1u) << spec.id() << " has no metadata";
    EXPECT_EQ(golden.text.at(image::png_keys::kStateHash), image::to_hex_hash(sidecar.state_hash)) << spec.id();
    EXPECT_EQ(golden.text.at(image::png_keys::kStep), std::to_string(sidecar.frame)) << spec.id();
    EXPECT_EQ(golden.text.at(image::png_keys::kRenderer), sidecar.renderer.describe()) << spec.id();
  }
}

}  // namespace
}  // namespace impulse2d::golden

/// @file test_golden_diff_command.cpp
/// `impulse2d diff a.png b.png [--out DIR]`: verdicts, exit statuses and the artifacts it
/// leaves.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "tests/golden/test_golden_temp_dir.h"
#include "golden/diff_command.h"
#include "image/file_io.h"
#include "image/image.h"
#include "image/png.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

class GoldenDiffCommand : public ::testing::Test {
 protected:
  GoldenDiffCommand() { image::save_png(a_, image::make_image(20, 10, image::Rgba{10, 20, 30, 255})); }
  /// Runs the command on a.png and `b`; fills out_ and err_.
  int run(const fs::path& b, const fs::path& out_dir = {}) {
    out_.str("");
    err_.str("");
    return run_diff_command(a_.string(), b.string(), out_dir.string(), out_, err_);
  }

  TempDir temp_;
  fs::path a_ = temp_.path() / "a.png";
  fs::path out_dir_ = temp_.path() / "out";
  std::ostringstream out_;
  std::ostringstream err_;
};

TEST_F(GoldenDiffCommand, IdenticalPixelsAreAnExactMatchAndWriteNothing) {
  const fs::path b = temp_.path() / "b.png";
  image::save_png(b, image::load_png(a_));
  EXPECT_EQ(run(b, out_dir_), kDiffSame);
  EXPECT_NE(out_.str().find("exact match"), std::string::npos) << out_.str();
  EXPECT_FALSE(fs::exists(out_dir_));
}

TEST_F(GoldenDiffCommand, DifferenceIsReportedWithEveryArtifact) {
  image::Image changed = image::load_png(a_);
  for (int y = 2; y < 7; ++y) {
    for (int x = 2; x < 7; ++x) changed.set_pixel(x, y, image::Rgba{250, 20, 30, 255});
  }
  const fs::path b = temp_.path() / "b.png";
  image::save_png(b, changed);
  EXPECT_EQ(run(b, out_dir_), kDiffDiffers);
  EXPECT_NE(out_.str().find("25 changed pixels"), std::string::npos) << out_.str();
  EXPECT_NE(out_.str().find("report: " + (out_dir_ / "index.html").string()), std::string::npos);
  for (const char* file :
       {"expected.png", "actual.png", "diff.png", "heatmap.png", "metrics.json", "index.html"}) {
    EXPECT_TRUE(fs::exists(out_dir_ / file)) << file;
  }
  EXPECT_NE(image::read_text_file(out_dir_ / "index.html").find("images differ"), std::string::npos);
  EXPECT_TRUE(err_.str().empty());
}

TEST_F(GoldenDiffCommand, WithoutOutDirOnlyTheVerdictIsPrinted) {
  image::Image changed = image::load_png(a_);
  changed.set_pixel(0, 0, image::Rgba{0, 0, 0, 255});
  const fs::path b = temp_.path() / "b.png";
  image::save_png(b, changed);
  EXPECT_EQ(run(b), kDiffDiffers);
  EXPECT_NE(out_.str().find("1 changed pixels"), std::string::npos) << out_.str();
  EXPECT_EQ(out_.str().find("report:"), std::string::npos);
}

TEST_F(GoldenDiffCommand, SizeMismatchDiffersWithoutDiffImages) {
  const fs::path b = temp_.path() / "b.png";
  image::save_png(b, image::make_image(21, 10, image::Rgba{10, 20, 30, 255}));
  EXPECT_EQ(run(b, out_dir_), kDiffDiffers);
  EXPECT_NE(out_.str().find("size mismatch: golden is 20x10, actual is 21x10"), std::string::npos)
      << out_.str();
  EXPECT_TRUE(fs::exists(out_dir_ / "actual.png"));
  EXPECT_FALSE(fs::exists(out_dir_ / "diff.png"));
}

TEST_F(GoldenDiffCommand, UnreadableInputIsAnErrorNamingTheFile) {
  const fs::path missing = temp_.path() / "missing.png";
  EXPECT_EQ(run(missing, out_dir_), kDiffError);
  EXPECT_NE(err_.str().find(missing.string()), std::string::npos) << err_.str();
  EXPECT_TRUE(out_.str().empty());
  EXPECT_FALSE(fs::exists(out_dir_));
}

TEST_F(GoldenDiffCommand, ThresholdAcceptsSmallDeltasOnly) {
  image::Image changed = image::load_png(a_);
  changed.set_pixel(3, 3, image::Rgba{11, 20, 30, 255});
  changed.set_pixel(4, 3, image::Rgba{10, 22, 30, 255});
  const fs::path b = temp_.path() / "b.png";
  image::save_png(b, changed);
  DiffLimits limits;
  limits.threshold = 2;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffSame);
  EXPECT_NE(out_.str().find("within tolerance"), std::string::npos) << out_.str();
  limits.threshold = 1;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffDiffers);
}

/// a.png with `count` pixels of row 5 changed from column 0 on.
fs::path with_changed_pixels(const fs::path& directory, const fs::path& a, int count) {
  image::Image changed = image::load_png(a);
  for (int x = 0; x < count; ++x) changed.set_pixel(x, 5, image::Rgba{200, 0, 0, 255});
  const fs::path b = directory / ("b" + std::to_string(count) + ".png");
  image::save_png(b, changed);
  return b;
}

TEST_F(GoldenDiffCommand, MaxDiffPixelsAndRatioAreEachALimit) {
  const fs::path b = with_changed_pixels(temp_.path(), a_, 4);  // 4 of 200 pixels: 0.02
  DiffLimits limits;
  limits.max_diff_pixels = 4;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffSame);
  limits.max_diff_pixels = 3;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffDiffers);
  limits.max_diff_pixels.reset();
  limits.max_diff_ratio = 0.02;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffSame);
  limits.max_diff_ratio = 0.019;
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffDiffers);
  limits.max_diff_pixels = 100;  // both given: both must hold
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffDiffers);
}

TEST_F(GoldenDiffCommand, MasksIgnoreTheirPixelsOnly) {
  const fs::path b = with_changed_pixels(temp_.path(), a_, 4);
  DiffLimits limits;
  limits.masks = {"0,5,2,1", "2,4,2,3"};
  out_.str("");
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffSame);
  EXPECT_NE(out_.str().find("4 changed pixels inside 2 masks ignored"), std::string::npos)
      << out_.str();
  limits.masks = {"0,5,3,1"};  // leaves the fourth pixel
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffDiffers);
}

TEST_F(GoldenDiffCommand, BadLimitsAreUsageErrorsNamingTheOption) {
  const fs::path b = with_changed_pixels(temp_.path(), a_, 1);
  const auto error_of = [&](const DiffLimits& limits) {
    err_.str("");
    EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, limits), kDiffError);
    return err_.str();
  };
  DiffLimits mask;
  mask.masks = {"1,2,3"};
  EXPECT_NE(error_of(mask).find("--mask '1,2,3': expected x,y,w,h"), std::string::npos);
  mask.masks = {"1,2,0,4"};
  EXPECT_NE(error_of(mask).find("width and height must be at least 1"), std::string::npos);
  DiffLimits ratio;
  ratio.max_diff_ratio = 1.5;
  EXPECT_NE(error_of(ratio).find("--max-diff-ratio"), std::string::npos);
  DiffLimits threshold;
  threshold.threshold = 256;
  EXPECT_NE(error_of(threshold).find("--threshold 256"), std::string::npos);
  DiffLimits pixels;
  pixels.max_diff_pixels = -1;
  EXPECT_NE(error_of(pixels).find("--max-diff-pixels -1"), std::string::npos);
}

/// A 20x10 frame with the metadata the golden tools write.
image::Image frame_with_metadata(const std::string& state_hash, const std::string& renderer) {
  image::Image image = image::make_image(20, 10, image::Rgba{10, 20, 30, 255});
  image.text = {{image::png_keys::kScene, "stack"},       {image::png_keys::kParameters, "defaults"},
                {image::png_keys::kStep, "60"},           {image::png_keys::kTime, "1"},
                {image::png_keys::kStateHash, state_hash}, {image::png_keys::kRenderer, renderer},
                {image::png_keys::kSoftware, "impulse2d 0.1.0"}};
  return image;
}

TEST_F(GoldenDiffCommand, MetadataRoundTripsAndTellsPhysicsFromPixels) {
  const fs::path a = temp_.path() / "meta_a.png";
  const fs::path b = temp_.path() / "meta_b.png";
  const fs::path c = temp_.path() / "meta_c.png";
  image::save_png(a, frame_with_metadata("00000000000000aa", "llvmpipe"));
  image::Image moved = frame_with_metadata("00000000000000bb", "llvmpipe");
  moved.set_pixel(3, 3, image::Rgba{200, 0, 0, 255});
  image::save_png(b, moved);
  image::Image redrawn = frame_with_metadata("00000000000000aa", "softpipe");
  redrawn.set_pixel(3, 3, image::Rgba{11, 20, 30, 255});
  image::save_png(c, redrawn);
  EXPECT_EQ(image::load_png(a).text.at(image::png_keys::kStateHash), "00000000000000aa");
  EXPECT_EQ(image::load_png(a).rgba, image::make_image(20, 10, image::Rgba{10, 20, 30, 255}).rgba);

  out_.str("");
  EXPECT_EQ(run_diff_command(a.string(), b.string(), "", out_, err_), kDiffDiffers);
  EXPECT_NE(out_.str().find("state 00000000000000aa"), std::string::npos) << out_.str();
  EXPECT_NE(out_.str().find("Physics state differs: simulation diverged"), std::string::npos)
      << out_.str();
  out_.str("");
  EXPECT_EQ(run_diff_command(a.string(), c.string(), "", out_, err_), kDiffDiffers);
  EXPECT_NE(out_.str().find("Same physics state, different renderers"), std::string::npos)
      << out_.str();
  out_.str("");
  EXPECT_EQ(run(b), kDiffDiffers);  // a.png of the fixture has no metadata: no verdict line
  EXPECT_EQ(out_.str().find("metadata:"), std::string::npos) << out_.str();
}

}  // namespace
}  // namespace impulse2d::golden

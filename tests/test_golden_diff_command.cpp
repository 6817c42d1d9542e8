/// @file test_golden_diff_command.cpp
/// `impulse2d diff a.png b.png [--out DIR]`: verdicts, exit statuses and the artifacts it
/// leaves.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "tests/test_golden_temp_dir.h"
#include "tools/golden/diff_command.h"
#include "tools/golden/file_io.h"
#include "tools/golden/image.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

class GoldenDiffCommand : public ::testing::Test {
 protected:
  GoldenDiffCommand() { save_png(a_, make_image(20, 10, Rgba{10, 20, 30, 255})); }
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
  save_png(b, load_png(a_));
  EXPECT_EQ(run(b, out_dir_), kDiffSame);
  EXPECT_NE(out_.str().find("exact match"), std::string::npos) << out_.str();
  EXPECT_FALSE(fs::exists(out_dir_));
}

TEST_F(GoldenDiffCommand, DifferenceIsReportedWithEveryArtifact) {
  Image changed = load_png(a_);
  for (int y = 2; y < 7; ++y) {
    for (int x = 2; x < 7; ++x) set_pixel(changed, x, y, Rgba{250, 20, 30, 255});
  }
  const fs::path b = temp_.path() / "b.png";
  save_png(b, changed);
  EXPECT_EQ(run(b, out_dir_), kDiffDiffers);
  EXPECT_NE(out_.str().find("25 changed pixels"), std::string::npos) << out_.str();
  EXPECT_NE(out_.str().find("report: " + (out_dir_ / "index.html").string()), std::string::npos);
  for (const char* file :
       {"expected.png", "actual.png", "diff.png", "heatmap.png", "metrics.json", "index.html"}) {
    EXPECT_TRUE(fs::exists(out_dir_ / file)) << file;
  }
  EXPECT_NE(read_text_file(out_dir_ / "index.html").find("images differ"), std::string::npos);
  EXPECT_TRUE(err_.str().empty());
}

TEST_F(GoldenDiffCommand, WithoutOutDirOnlyTheVerdictIsPrinted) {
  Image changed = load_png(a_);
  set_pixel(changed, 0, 0, Rgba{0, 0, 0, 255});
  const fs::path b = temp_.path() / "b.png";
  save_png(b, changed);
  EXPECT_EQ(run(b), kDiffDiffers);
  EXPECT_NE(out_.str().find("1 changed pixels"), std::string::npos) << out_.str();
  EXPECT_EQ(out_.str().find("report:"), std::string::npos);
}

TEST_F(GoldenDiffCommand, SizeMismatchDiffersWithoutDiffImages) {
  const fs::path b = temp_.path() / "b.png";
  save_png(b, make_image(21, 10, Rgba{10, 20, 30, 255}));
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

TEST_F(GoldenDiffCommand, ToleranceCanAcceptSmallDeltas) {
  Image changed = load_png(a_);
  set_pixel(changed, 3, 3, Rgba{11, 20, 30, 255});
  const fs::path b = temp_.path() / "b.png";
  save_png(b, changed);
  Tolerance tolerance;
  tolerance.max_channel_delta = 1;
  out_.str("");
  EXPECT_EQ(run_diff_command(a_.string(), b.string(), "", out_, err_, tolerance), kDiffSame);
  EXPECT_NE(out_.str().find("within tolerance"), std::string::npos) << out_.str();
}

}  // namespace
}  // namespace impulse2d::golden

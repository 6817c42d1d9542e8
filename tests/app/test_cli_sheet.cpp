// Contact sheets (issue 15.3): tiles framed by borders and separated by gutters (so a ground
// strip never runs into the next tile), a title with the parameters and overlays, --trails,
// and a sheet too large refused before anything runs or renders.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <string>

#include "frames/contact_sheet.h"
#include "scene/overlays.h"
#include "tests/support/cli_test_support.h"
#include "image/image.h"
#include "image/png.h"

using namespace cli_test;

namespace {

/// The RGBA of pixel (x, y).
std::array<std::uint8_t, 4> pixel(const impulse2d::image::Image& image, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

}  // namespace

TEST_F(CliTest, SheetTilesHaveBordersAndGutters) {
  const Result result = run("sheet stack --count 2 --columns 2 --tile 64x48 -o s.png");
  ASSERT_EQ(result.status, 0) << result.err;
  const impulse2d::image::Image sheet = impulse2d::image::load_png(dir_ / "s.png");
  // 10-pixel gutters around and between the tiles, a 50-pixel title, a 22-pixel label strip.
  ASSERT_EQ(sheet.width, 2 * (64 + 10) + 10);
  ASSERT_EQ(sheet.height, 50 + 48 + 22 + 10 + 10);
  const auto background = pixel(sheet, 4, sheet.height - 3);
  const int top = 50 + 10;  // the first row of tiles
  EXPECT_EQ(pixel(sheet, 4, top + 20), background);           // the left gutter
  EXPECT_EQ(pixel(sheet, 10 + 64 + 5, top + 20), background);  // between the tiles
  EXPECT_NE(pixel(sheet, 9, top + 20), background);            // the first tile's left border
  EXPECT_NE(pixel(sheet, 10 + 64, top + 20), background);      // its right border
  EXPECT_NE(pixel(sheet, 30, top - 1), background);            // its top border
}

// --scenes: several scenes' tiles on one sheet, in the order given, each scene's own tiles the
// same as on its own sheet.
TEST_F(CliTest, SheetOfSeveralScenesTilesThemInOrder) {
  const Result both = run("sheet --scenes stack,pendulum --frames 30 --tile 64x48 -o both.png");
  ASSERT_EQ(both.status, 0) << both.err;
  EXPECT_NE(both.out.find("of 2 frames of 2 scenes"), std::string::npos) << both.out;
  const impulse2d::image::Image sheet = impulse2d::image::load_png(dir_ / "both.png");
  ASSERT_EQ(sheet.width, 2 * (64 + 10) + 10);
  ASSERT_EQ(sheet.height, 50 + 48 + 22 + 10 + 10);
  ASSERT_EQ(run("sheet stack --frames 30 --tile 64x48 -o stack.png").status, 0);
  ASSERT_EQ(run("sheet pendulum --frames 30 --tile 64x48 -o pendulum.png").status, 0);
  const impulse2d::image::Image stack = impulse2d::image::load_png(dir_ / "stack.png");
  const impulse2d::image::Image pendulum = impulse2d::image::load_png(dir_ / "pendulum.png");
  const int top = 50 + 10;
  for (int y = 0; y < 48; ++y) {
    for (int x = 0; x < 64; ++x) {
      ASSERT_EQ(pixel(sheet, 10 + x, top + y), pixel(stack, 10 + x, top + y)) << x << "," << y;
      ASSERT_EQ(pixel(sheet, 10 + 74 + x, top + y), pixel(pendulum, 10 + x, top + y)) << x << "," << y;
    }
  }
}

TEST_F(CliTest, SheetTrailsAddTheBodiesPaths) {
  ASSERT_EQ(run("sheet tutorial --frames 120 --tile 160x120 -o plain.png").status, 0);
  const Result trails = run("sheet tutorial --frames 120 --tile 160x120 --trails dynamic -o t.png");
  ASSERT_EQ(trails.status, 0) << trails.err;
  EXPECT_EQ(run("diff plain.png t.png").status, 1);
  const Result bad = run("sheet tutorial --frames 120 --trails 999 -o u.png");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--trails: body 999 does not exist"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "u.png"));
}

TEST_F(CliTest, SheetTooLargeIsRefusedBeforeAnythingRuns) {
  const auto start = std::chrono::steady_clock::now();
  const Result result = run("sheet ball_pit --count 64 --tile 2000x1500 -o big.png");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("impulse2d: sheet: 64 tiles of 2000x1500 in 4 columns make a "
                            "8050x24572 sheet; the limits are 8192 pixels a side"),
            std::string::npos)
      << result.err;
  EXPECT_LT(seconds, 5.0);  // no simulation, no rendering
  EXPECT_TRUE(files().empty());
}

TEST(SheetTitle, NamesTheOverlaysByTheirOptionNames) {
  using impulse2d::demos::overlay_list;
  using impulse2d::demos::parse_overlays;
  EXPECT_EQ(overlay_list(0), "none");
  EXPECT_EQ(overlay_list(parse_overlays("normals,penetration")), "normals, penetration");
  EXPECT_EQ(overlay_list(parse_overlays("contacts")), "contacts");
  EXPECT_EQ(overlay_list(parse_overlays("points,ids")), "points, ids");
}

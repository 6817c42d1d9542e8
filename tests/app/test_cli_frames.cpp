// Frames other tools can read (issue 15.4, 11.6): `impulse2d render` numbers its PNGs 0, 1,
// 2, ... whatever steps they show, indexes them in <scene>_frames.csv, records scene,
// parameters, step, time, state hash, renderer and version in every PNG's tEXt metadata (read
// by `impulse2d diff`), and writes .mp4 / .webm / .gif videos at --fps, with or without frames.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"
#include "image/png_text.h"

using namespace cli_test;
namespace keys = impulse2d::image::png_keys;

namespace {

/// The tEXt metadata of a PNG file.
impulse2d::image::PngText png_text_of(const fs::path& path) {
  const std::string bytes = read_file(path);
  return impulse2d::image::read_png_text(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

/// What `command` prints (its first line), or "" when it fails.
std::string first_line_of(const std::string& command) {
  std::string line;
  if (std::FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    if (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) line = buffer;
    pclose(pipe);
  }
  if (!line.empty() && line.back() == '\n') line.pop_back();
  return line;
}

}  // namespace

TEST_F(CliTest, FramesAreNumberedContiguouslyAndIndexed) {
  const Result result =
      run("render pyramid -p rows=3 --frames 0:40:10 --size 96x64 -o f");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("f/pyramid_00000.png .. f/pyramid_00004.png, index "
                            "f/pyramid_frames.csv"),
            std::string::npos)
      << result.out;
  for (int frame = 0; frame < 5; ++frame) {
    char name[32];
    std::snprintf(name, sizeof(name), "f/pyramid_%05d.png", frame);
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  }
  EXPECT_EQ(files().size(), 6u);
  EXPECT_EQ(read_file(dir_ / "f/pyramid_frames.csv"),
            "frame,step,time,file\n"
            "0,0,0,pyramid_00000.png\n"
            "1,10,0.166666675,pyramid_00001.png\n"
            "2,20,0.333333351,pyramid_00002.png\n"
            "3,30,0.500000026,pyramid_00003.png\n"
            "4,40,0.666666701,pyramid_00004.png\n");
}

TEST_F(CliTest, EveryFrameCarriesItsMetadata) {
  ASSERT_EQ(run("render pyramid -p rows=3 --frames 0,30 --size 96x64 -o f").status, 0);
  const impulse2d::image::PngText text = png_text_of(dir_ / "f/pyramid_00001.png");
  EXPECT_EQ(text.at(keys::kScene), "pyramid");
  EXPECT_EQ(text.at(keys::kParameters), "rows=3");
  EXPECT_EQ(text.at(keys::kStep), "30");
  EXPECT_EQ(text.at(keys::kTime), "0.500000026");
  EXPECT_EQ(text.at(keys::kStateHash).size(), 16u);
  EXPECT_NE(text.at(keys::kRenderer).find(" / "), std::string::npos) << text.at(keys::kRenderer);
  EXPECT_EQ(text.at(keys::kSoftware).rfind("impulse2d ", 0), 0u);
  EXPECT_EQ(png_text_of(dir_ / "f/pyramid_00000.png").at(keys::kStep), "0");
  // The default parameters say so.
  ASSERT_EQ(run("render bullet --frames 0 --size 64x64 -o g").status, 0);
  EXPECT_EQ(png_text_of(dir_ / "g/bullet_00000.png").at(keys::kParameters), "defaults");
}

// `diff` reads the metadata: two frames of one state in two themes differ in pixels only.
TEST_F(CliTest, DiffClassifiesRenderedFramesByTheirMetadata) {
  ASSERT_EQ(run("render pyramid -p rows=3 --frames 0,30 --size 96x64 -o light").status, 0);
  ASSERT_EQ(run("render pyramid -p rows=3 --frames 30 --size 96x64 -o dark --theme dark").status,
            0);
  const Result pixels = run("diff light/pyramid_00001.png dark/pyramid_00000.png");
  EXPECT_EQ(pixels.status, 1);
  EXPECT_NE(pixels.out.find("metadata: a is pyramid step 30"), std::string::npos) << pixels.out;
  EXPECT_NE(pixels.out.find("Same physics state and renderer"), std::string::npos) << pixels.out;
  const Result steps = run("diff light/pyramid_00000.png light/pyramid_00001.png");
  EXPECT_NE(steps.out.find("frames of different scenes, steps or parameters"), std::string::npos)
      << steps.out;
}

TEST_F(CliTest, WebmVideoAtTheAskedRateWithoutFrames) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed (optional: apt-get install ffmpeg)";
  const Result result = run(
      "render pyramid -p rows=3 --frames 0:40:4 --size 96x64 --video clip.webm --fps 12 "
      "--no-frames -o frames");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(files(), std::vector<std::string>{"clip.webm"});  // no frames, no frames/ directory
  EXPECT_EQ(read_file(dir_ / "clip.webm").substr(0, 4), "\x1a\x45\xdf\xa3");  // EBML (Matroska)
  EXPECT_NE(result.out.find("wrote 11 frames of pyramid to clip.webm"), std::string::npos)
      << result.out;
  if (std::system("command -v ffprobe > /dev/null 2>&1") == 0) {
    // Width, height, rate and the frames decoded: all 11 rendered, none dropped or repeated.
    EXPECT_EQ(first_line_of("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                            "stream=width,height,r_frame_rate,nb_read_frames -of csv=p=0 '" +
                            (dir_ / "clip.webm").string() + "'"),
              "96,64,12/1,11");
  }
}

TEST_F(CliTest, GifVideoBesideTheFrames) {
  if (!have_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed (optional: apt-get install ffmpeg)";
  const Result result =
      run("render pyramid -p rows=3 --frames 0:20:10 --size 96x64 --video f/clip.gif -o f");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_EQ(read_file(dir_ / "f/clip.gif").substr(0, 4), "GIF8");
  EXPECT_TRUE(fs::exists(dir_ / "f/pyramid_00002.png"));
}

TEST_F(CliTest, BadFpsIsBadUsage) {
  const Result result = run("render pyramid --frames 0 --video v.webm --fps 0");
  EXPECT_EQ(result.status, 2);
  EXPECT_NE(result.err.find("--fps 0: must be 1..240"), std::string::npos) << result.err;
  EXPECT_TRUE(files().empty());
}

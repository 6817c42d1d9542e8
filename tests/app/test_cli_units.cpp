// The command line's helpers in process: "did you mean" spelling, the progress bar's width
// and ETA, and frame-number widths.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "frames/frame_index.h"
#include "frames/progress.h"
#include "app/spelling.h"
#include "render/frame_writer.h"

using namespace impulse2d::demos;

TEST(Spelling, SuggestsTheClosestKnownName) {
  const std::vector<std::string> commands = {"list", "render", "trace", "sheet", "diff", "golden"};
  EXPECT_EQ(closest_spelling("rendr", commands), "render");
  EXPECT_EQ(closest_spelling("rnder", commands), "render");
  EXPECT_EQ(closest_spelling("tarce", commands), "trace");  // a swap is one edit
  EXPECT_EQ(closest_spelling("shet", commands), "sheet");
  EXPECT_EQ(closest_spelling("gold", commands), "golden");  // a prefix
  EXPECT_FALSE(closest_spelling("explode", commands));
  EXPECT_FALSE(closest_spelling("", commands));
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("", "abc"), 3);
}

TEST(FrameNumbers, AreWideEnoughForTheRunAndAtLeastFiveDigits) {
  EXPECT_EQ(frame_number_digits(1), 5);
  EXPECT_EQ(frame_number_digits(100000), 5);  // the last frame is 99999
  EXPECT_EQ(frame_number_digits(100001), 6);
  EXPECT_EQ(frame_number_digits(12345678), 8);
  EXPECT_EQ(impulse2d::render::frame_file_path("d", "s", 42, 6), std::filesystem::path("d/s_000042.png"));
  EXPECT_EQ(frame_index_path("d", "s"), std::filesystem::path("d/s_frames.csv"));
}

namespace {

/// The lines a terminal progress bar drew into `file` (split at carriage returns, without the
/// clear-to-end-of-line escape).
std::vector<std::string> drawn_lines(std::FILE* file) {
  std::rewind(file);
  std::string text;
  for (int c; (c = std::fgetc(file)) != EOF;) text += static_cast<char>(c);
  std::vector<std::string> lines;
  std::string line;
  for (const char c : text) {
    if (c == '\r' || c == '\n') {
      const std::size_t escape = line.find("\033[K");
      if (escape != std::string::npos) line.erase(escape);
      if (!line.empty()) lines.push_back(line);
      line.clear();
    } else {
      line += c;
    }
  }
  return lines;
}

}  // namespace

TEST(ProgressBar, FitsA60ColumnTerminalAndWaitsForWarmUpBeforeItsEta) {
  setenv("COLUMNS", "60", 1);
  EXPECT_EQ(terminal_columns(stderr), 60);
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    Progress progress("a_rather_long_scene_name", 200000, file, true);
    for (std::int64_t done = 1; done <= 200000; done += 40000) progress.update(done);
    progress.update(200000);
    progress.finish();
  }
  const std::vector<std::string> lines = drawn_lines(file);
  std::fclose(file);
  unsetenv("COLUMNS");
  ASSERT_GE(lines.size(), 2u);
  for (const std::string& line : lines) EXPECT_LT(line.size(), 60u) << line;
  EXPECT_NE(lines.front().find("ETA ..."), std::string::npos) << lines.front();
  EXPECT_NE(lines.back().find("200000/200000"), std::string::npos) << lines.back();
}

TEST(ProgressBar, NarrowTerminalsStillGetOneLine) {
  setenv("COLUMNS", "20", 1);
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    Progress progress("tutorial", 301, file, true);
    progress.update(1);
    progress.update(301);
  }
  const std::vector<std::string> lines = drawn_lines(file);
  std::fclose(file);
  unsetenv("COLUMNS");
  ASSERT_FALSE(lines.empty());
  for (const std::string& line : lines) EXPECT_LT(line.size(), 20u) << line;
}

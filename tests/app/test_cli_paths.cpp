// Every path a user gives the program is a file name and nothing else: a folder and files
// whose names hold quotes, spaces, `$`, `;`, a backslash and a newline are read and written as
// named (scene file, frames, index, viewer, sheet, diff report; trace reads one), and no shell ever
// sees them (a `touch` inside a name runs nothing).
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_test_support.h"

using namespace cli_test;

namespace {

/// A name holding every character a shell would act on.
const std::string hostile = "a 'q' \"d\" $HOME ; touch PWNED ; `touch PWNED2` \\ \nline";

/// `text` as one single-quoted shell word (for the test's own shell only).
std::string shell_word(const std::string& text) {
  std::string word = "'";
  for (const char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

// Named: a scene's file name becomes its name (the frames' prefix) only when it is a safe one.
const char* const falling_ball = R"({
  "name": "ball",
  "bodies": [
    {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [4, 0.5]}, "position": [0, -0.5]},
    {"name": "ball", "shape": {"type": "circle", "radius": 0.5}, "position": [0, 2]}],
  "run": {"steps": 20, "frames": "0:20:10"}
})";

class CliPaths : public CliTest {
 protected:
  /// Fails when a shell ran a command hidden in a name.
  void expect_no_command_ran() const {
    for (const std::string& file : files()) {
      const std::string name = fs::path(file).filename().string();
      EXPECT_TRUE(name != "PWNED" && name != "PWNED2") << "a shell ran: " << file;
    }
  }
};

TEST_F(CliPaths, RenderReadsAndWritesHostileNames) {
  fs::create_directories(dir_ / hostile);
  write_file(dir_ / hostile / (hostile + ".json"), falling_ball);
  const std::string scene = hostile + "/" + hostile + ".json";
  const std::string out = hostile + "/frames " + hostile;
  const Result result = run("render " + shell_word(scene) + " --size 96x72 -o " + shell_word(out) + " --html");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string stem = "ball";
  EXPECT_TRUE(fs::is_regular_file(dir_ / out / (stem + "_00000.png"))) << result.out;
  EXPECT_TRUE(fs::is_regular_file(dir_ / out / (stem + "_00002.png")));
  EXPECT_TRUE(fs::is_regular_file(dir_ / out / (stem + "_frames.csv")));
  EXPECT_TRUE(fs::is_regular_file(dir_ / out / (stem + ".html")));
  expect_no_command_ran();
}

TEST_F(CliPaths, SheetTraceAndDiffTakeHostileNames) {
  write_file(dir_ / (hostile + ".json"), falling_ball);
  const std::string scene = shell_word(hostile + ".json");

  const Result sheet = run("sheet " + scene + " --tile 64x48 --count 2 -o " + shell_word(hostile + ".png"));
  ASSERT_EQ(sheet.status, 0) << sheet.err;
  EXPECT_EQ(read_file(dir_ / (hostile + ".png")).substr(1, 3), "PNG");

  const Result trace = run("trace " + scene);
  ASSERT_EQ(trace.status, 0) << trace.err;
  EXPECT_EQ(trace.out.rfind("step,t,body,", 0), 0u) << trace.out;

  // Two different sheets: diff writes its report into a hostile folder.
  const Result other = run("sheet " + scene + " --tile 64x48 --count 3 --columns 3 -o b.png");
  ASSERT_EQ(other.status, 0) << other.err;
  const Result diff =
      run("diff " + shell_word(hostile + ".png") + " b.png -o " + shell_word(hostile + " report"));
  EXPECT_NE(diff.status, 2) << diff.err;
  expect_no_command_ran();
}

}  // namespace

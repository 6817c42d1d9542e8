// `impulse2d lab`, `lab merge` and `tune` as subprocesses: a --quick run writes its CSV and
// charts, two shards merged equal one run's configurations, and bad input exits 2 with a message
// and leaves no file behind.
#include "lab/lab_result.h"
#include "tests/support/cli_test_support.h"

namespace {

using cli_test::read_file;
using cli_test::Result;
namespace fs = std::filesystem;

/// The CLI fixture plus the lab's CSV read back.
class LabCliTest : public cli_test::CliTest {
 protected:
  std::vector<impulse2d::lab::LabResult> csv(const std::string& name) const {
    return impulse2d::lab::parse_csv(read_file(dir_ / name), name);
  }
};

const char* const quick_subset =
    "lab --quick --only projectile,elastic_collision,stack_10 --no-stability --repeats 1";

TEST_F(LabCliTest, QuickRunWritesCsvAndOneChartPerScenario) {
  const Result result = run(std::string(quick_subset) + " --out lab");
  ASSERT_EQ(result.status, 0) << result.err;
  const auto rows = csv("lab/lab.csv");
  EXPECT_GE(rows.size(), 3u * 19u);
  int recommended = 0;
  for (const auto& row : rows) recommended += row.recommended ? 1 : 0;
  EXPECT_EQ(recommended, 3);  // every one of these scenarios has a passing method
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    for (const char* name : {"projectile", "elastic_collision", "stack_10"}) {
      EXPECT_TRUE(fs::exists(dir_ / "lab" / "charts" / (std::string(name) + ".png"))) << name;
    }
  }
  for (const auto& entry : fs::recursive_directory_iterator(dir_ / "lab")) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

/// `text` as one word for /bin/sh (single quotes, each ' written as '\'').
std::string shell_word(const std::string& text) {
  std::string word = "'";
  for (const char c : text) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

/// Every file under `root` named PWNED (what a shell reading a path would have created).
std::vector<std::string> stray_files(const fs::path& root) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().filename() == "PWNED") found.push_back(entry.path().string());
  }
  return found;
}

// gnuplot is started without a shell and never sees a path: an --out with a quote, `;touch`,
// `$`, a double quote, a newline and a leading '-' runs nothing and still gets its charts.
TEST_F(LabCliTest, OutPathIsNeverReadByAShell) {
  const std::string out = "-x'; touch PWNED; 'y $HOME \"q\"\nz";
  const Result result =
      run("lab --quick --only projectile --repeats 1 --out=" + shell_word(out));
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_TRUE(fs::exists(dir_ / out / "lab.csv"));
  EXPECT_TRUE(fs::exists(dir_ / out / "stability.csv"));
  if (std::system("command -v gnuplot >/dev/null 2>&1") == 0) {
    for (const char* chart : {"charts/projectile.png", "stability.png"}) {
      EXPECT_EQ(read_file(dir_ / out / chart).substr(1, 3), "PNG") << chart << result.out;
    }
  }
  EXPECT_TRUE(stray_files(dir_).empty());
  for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

// When gnuplot fails, the message says how (exit status and its complaint, or that it drew
// nothing): never an empty reason.
TEST_F(LabCliTest, FailingGnuplotSaysWhy) {
  fs::create_directories(dir_ / "bin");
  cli_test::write_file(dir_ / "bin/gnuplot",
                       "#!/bin/sh\ncat > /dev/null\necho 'fake gnuplot: line 3: no' >&2\nexit 1\n");
  fs::permissions(dir_ / "bin/gnuplot", fs::perms::owner_all);
  const std::string subset = "lab --quick --only projectile --no-stability --repeats 1";
  const Result failing = run(subset + " --out a", "PATH=\"$PWD/bin:$PATH\"");
  EXPECT_EQ(failing.status, 1);
  EXPECT_NE(failing.err.find("gnuplot failed drawing a/charts/projectile.png: exit status 1: "
                             "fake gnuplot: line 3: no"),
            std::string::npos)
      << failing.err;
  cli_test::write_file(dir_ / "bin/gnuplot", "#!/bin/sh\ncat > /dev/null\n");
  const Result silent = run(subset + " --out b", "PATH=\"$PWD/bin:$PATH\"");
  EXPECT_EQ(silent.status, 1);
  EXPECT_NE(silent.err.find("gnuplot failed drawing b/charts/projectile.png: it drew no image"),
            std::string::npos)
      << silent.err;
  for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

TEST_F(LabCliTest, TwoShardsMergedCoverEveryConfigurationOnce) {
  ASSERT_EQ(run(std::string(quick_subset) + " --shard 1/2 --out a").status, 0);
  ASSERT_EQ(run(std::string(quick_subset) + " --shard 2/2 --out b").status, 0);
  ASSERT_EQ(run(std::string(quick_subset) + " --no-charts --out whole").status, 0);
  const Result merged =
      run("lab merge a/lab_shard_1_of_2.csv b/lab_shard_2_of_2.csv --no-charts --out merged");
  ASSERT_EQ(merged.status, 0) << merged.err;
  const auto joined = csv("merged/lab.csv");
  const auto whole = csv("whole/lab.csv");
  ASSERT_EQ(joined.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(joined[i].job, whole[i].job);
    EXPECT_EQ(joined[i].scenario, whole[i].scenario);
    EXPECT_EQ(joined[i].error, whole[i].error);  // errors are deterministic; only times differ
  }
  const Result twice = run("lab merge a/lab_shard_1_of_2.csv a/lab_shard_1_of_2.csv --out again");
  EXPECT_EQ(twice.status, 2);
  EXPECT_NE(twice.err.find("appears twice"), std::string::npos) << twice.err;
  EXPECT_FALSE(fs::exists(dir_ / "again"));
}

TEST_F(LabCliTest, BadInputExitsTwoWithAMessageAndWritesNothing) {
  const Result shard = run("lab --shard 3/2 --out out");
  EXPECT_EQ(shard.status, 2);
  EXPECT_NE(shard.err.find("--shard '3/2'"), std::string::npos) << shard.err;
  const Result only = run("lab --only nosuch --out out");
  EXPECT_EQ(only.status, 2);
  EXPECT_NE(only.err.find("--only nosuch: no such scenario"), std::string::npos) << only.err;
  const Result tune = run("tune pyramid --max-error -1");
  EXPECT_EQ(tune.status, 2);
  EXPECT_NE(tune.err.find("--max-error '-1': expected a number in (0, 1000] m"), std::string::npos) << tune.err;
  const Result metric = run("tune pyramid --max-error 0.1 --metric nope");
  EXPECT_EQ(metric.status, 2);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(LabCliTest, TunePrintsJsonSettingsThatTheSceneLoaderAccepts) {
  const Result result = run("tune pyramid --param rows=6 --max-error 0.05 --duration 3 --quick --repeats 1");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::size_t open = result.out.find("{\n  \"settings\"");
  ASSERT_NE(open, std::string::npos) << result.out;
  // Paste the printed settings into a scene file and load it.
  std::string scene = result.out.substr(open);
  scene.insert(scene.rfind('}'), R"(, "bodies": [{"shape": {"type": "box", "half_extents": [1, 1]}, "position": [0, 0]}])");
  std::ofstream(dir_ / "tuned.json") << scene;
  const Result trace = run("trace tuned.json --steps 2");
  EXPECT_EQ(trace.status, 0) << trace.err << scene;
  // Float settings print in their shortest form (a 2 cm margin as 0.02, not 0.0199999996).
  EXPECT_EQ(result.out.find("0.0199999"), std::string::npos) << result.out;
}

}  // namespace

// The lab's output rules: strict option numbers, JSON numbers in shortest form, the work budget,
// and the output folder as a transaction (another run's results refused, a failure leaves the
// folder as it was, a commit replaces what --clean names).
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "lab/json_number.h"
#include "lab/lab_command.h"
#include "lab/lab_output.h"
#include "lab/option_numbers.h"
#include "lab/work_budget.h"
#include "scene/interrupt.h"
#include "scene/usage_error.h"

namespace {

using namespace impulse2d;
namespace fs = std::filesystem;

TEST(LabOptionNumbers, CountsAreDigitsWithinTheirRange) {
  EXPECT_EQ(lab::count_option("--repeats", "3", 1, 100), 3);
  for (const char* bad : {"", "0", "101", "+3", " 3", "3 ", "0x3", "3k", "-1", "1e2"}) {
    EXPECT_THROW(lab::count_option("--repeats", bad, 1, 100), demos::UsageError) << bad;
  }
}

TEST(LabOptionNumbers, BoundsAreFiniteDecimalsWithinTheirRange) {
  EXPECT_DOUBLE_EQ(lab::decimal_option("--max-error", "0.05", 0.0, 1000.0, "m"), 0.05);
  EXPECT_DOUBLE_EQ(lab::decimal_option("--max-error", "1e-3", 0.0, 1000.0, "m"), 1e-3);
  for (const char* bad : {"inf", "nan", "0", "-1", "1e999", "0x1p-3", " 1", "+1", "1001"}) {
    try {
      lab::decimal_option("--max-error", bad, 0.0, 1000.0, "m");
      ADD_FAILURE() << bad << " accepted";
    } catch (const demos::UsageError& error) {
      EXPECT_NE(std::string(error.what()).find("--max-error '" + std::string(bad) + "'"), std::string::npos);
      EXPECT_NE(std::string(error.what()).find("(0, 1000] m"), std::string::npos) << error.what();
    }
  }
}

TEST(LabJsonNumber, FloatsPrintInTheirShortestForm) {
  nlohmann::json document;
  document["margin"] = lab::json_number(0.02f, "margin");
  document["step"] = lab::json_number(1.0f / 60.0f, "step");
  EXPECT_EQ(document.dump(), R"({"margin":0.02,"step":0.016666668})");
  EXPECT_EQ(static_cast<float>(document["step"].get<double>()), 1.0f / 60.0f);
}

TEST(LabJsonNumber, NonFiniteValuesAreRefused) {
  EXPECT_THROW(lab::json_number(std::numeric_limits<float>::infinity(), "x"), std::logic_error);
  EXPECT_THROW(lab::json_number(std::nan(""), "x"), std::logic_error);
}

TEST(LabWorkBudget, RefusesAboveTheBoundWithoutForceAndStatesTheEstimate) {
  lab::WorkEstimate work;
  work.runs = 121600;
  work.steps = 80000000;
  work.seconds = 2700.0;
  EXPECT_EQ(lab::grouped(121600), "121,600");
  EXPECT_EQ(lab::grouped(999), "999");
  try {
    lab::check_budget("lab", work, work.runs, lab::max_lab_runs, "runs", false, "fewer --repeats");
    ADD_FAILURE() << "not refused";
  } catch (const demos::UsageError& error) {
    EXPECT_EQ(std::string(error.what()),
              "lab: 121,600 runs, 80,000,000 steps (about 45 min on this machine) exceeds the bound "
              "of 20,000 runs without --force (fewer --repeats make it smaller)");
  }
  EXPECT_NO_THROW(lab::check_budget("lab", work, work.runs, lab::max_lab_runs, "runs", true, ""));
}

/// A scratch folder removed at the end.
class LabOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("impulse2d_lab_output_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  std::string read(const fs::path& path) {
    std::ifstream file(path);
    return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  fs::path root_;
};

TEST_F(LabOutputTest, AnotherRunsResultsAreFoundAndSiblingShardsAreNot) {
  const fs::path out = root_ / "out";
  write(out / "lab_shard_1_of_2.csv", "a");
  write(out / "notes.txt", "mine");
  EXPECT_TRUE(lab::other_runs_results(out, {"lab_shard_2_of_2.csv"}, 2).empty());
  EXPECT_EQ(lab::other_runs_results(out, {"lab_shard_1_of_2.csv"}, 2),
            std::vector<std::string>{"lab_shard_1_of_2.csv"});
  EXPECT_EQ(lab::other_runs_results(out, {"lab.csv"}, 1), std::vector<std::string>{"lab_shard_1_of_2.csv"});
  EXPECT_TRUE(lab::other_runs_results(out, {"lab.csv", "charts"}, 0).empty());  // merge's inputs
  EXPECT_THROW(lab::check_output_directory(out, {"lab_shard_1_of_2.csv"}, false, "--out"), demos::UsageError);
  EXPECT_NO_THROW(lab::check_output_directory(out, {"lab_shard_1_of_2.csv"}, true, "--out"));
  EXPECT_THROW(lab::check_output_directory(out / "notes.txt", {}, false, "--out"), demos::UsageError);
}

TEST_F(LabOutputTest, AFailedRunLeavesTheFolderAsItWas) {
  const fs::path out = root_ / "out";
  write(out / "lab.csv", "old");
  try {
    lab::OutputTransaction output(out, {"lab.csv"});
    write(output.staging() / "lab.csv", "new");
    throw std::runtime_error("failed half-way");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read(out / "lab.csv"), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  {
    lab::OutputTransaction output(root_ / "fresh" / "deeper", {});
    write(output.staging() / "lab.csv", "new");
  }
  EXPECT_FALSE(fs::exists(root_ / "fresh"));
}

TEST_F(LabOutputTest, ACommitReplacesWhatCleanNamesAndMovesEverythingIn) {
  const fs::path out = root_ / "out";
  write(out / "lab.csv", "old");
  write(out / "charts" / "old.png", "old chart");
  write(out / "notes.txt", "keep");
  {
    lab::OutputTransaction output(out, {"charts", "lab.csv"});
    write(output.staging() / "lab.csv", "new");
    write(output.staging() / "charts" / "new.png", "new chart");
    EXPECT_EQ(output.in_output_terms("cannot write " + (output.staging() / "lab.csv").string()),
              "cannot write " + (out / "lab.csv").string());
    output.commit();
  }
  EXPECT_EQ(read(out / "lab.csv"), "new");
  EXPECT_TRUE(fs::exists(out / "charts" / "new.png"));
  EXPECT_FALSE(fs::exists(out / "charts" / "old.png"));
  EXPECT_EQ(read(out / "notes.txt"), "keep");
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 3);  // no staging left
}

// A signal that arrives while `lab` still plans (it steps each scenario to estimate the work) is
// worded like one during the work: nothing written, --out as it was. The signal is raised before
// the run, so the planning is what it stops; a child process runs it, since a received signal
// cannot be taken back.
TEST(LabInterrupt, ASignalWhilePlanningSaysNothingWasWritten) {
  const fs::path out = fs::temp_directory_path() / "impulse2d_lab_interrupted_while_planning";
  fs::remove_all(out);
  EXPECT_EXIT(
      {
        demos::install_interrupt_handlers();
        std::raise(SIGINT);
        lab::LabArguments arguments;
        arguments.quick = true;
        arguments.only = {"pyramid_20"};
        arguments.stability = false;
        arguments.quiet = true;
        arguments.out = out.string();
        std::ostringstream report;
        try {
          lab::run_lab(arguments, report);
        } catch (const demos::Interrupted& interrupted) {
          std::fprintf(stderr, "%s\n", interrupted.what());
          std::exit(interrupted.exit_status());
        }
        std::exit(0);
      },
      ::testing::ExitedWithCode(128 + SIGINT),
      "^lab interrupted by SIGINT: nothing written, .*impulse2d_lab_interrupted_while_planning is as it was");
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

/// @file test_golden_staged_update.cpp
/// `golden update`'s transaction (golden/staged_update.h) on plain files: the golden folder
/// holds the whole old set or the whole new one, and a PNG is never beside another set's
/// sidecar, whether the update fails between writes, a swap fails, or the process dies
/// half-way through its commit (the next run rolls it forward); plus the JSON the golden
/// code writes (shortest numbers, floats as floats, no non-finite values) and the output
/// path checks made before any work.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "golden/error.h"
#include "golden/json_output.h"
#include "golden/output_path.h"
#include "golden/sidecar.h"
#include "golden/staged_update.h"
#include "image/file_io.h"
#include "tests/golden/test_golden_temp_dir.h"

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

/// Writes one golden "pair" of set `set` (the PNG and sidecar stand-ins name their set).
void write_pair(const fs::path& folder, const std::string& id, const std::string& set) {
  image::write_text_file_atomically(folder / (id + ".png"), "png of " + set);
  image::write_text_file_atomically(folder / (id + ".json"), "sidecar of " + set);
}

/// Every file under `folder` (relative path -> contents), hidden staging excluded.
std::map<std::string, std::string> files_of(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    if (entry.is_regular_file()) {
      files[entry.path().lexically_relative(folder).string()] = image::read_text_file(entry.path());
    }
  }
  return files;
}

/// What a check would see: for each pair, the set its PNG and its sidecar belong to; fails
/// the test for a split pair.
std::map<std::string, std::string> sets_of_pairs(const fs::path& folder) {
  std::map<std::string, std::string> sets;
  for (const auto& [path, contents] : files_of(folder)) {
    if (fs::path(path).extension() != ".png") continue;
    const std::string set = contents.substr(std::string("png of ").size());
    const fs::path sidecar = folder / fs::path(path).replace_extension(".json");
    EXPECT_EQ(image::read_text_file(sidecar), "sidecar of " + set) << "split pair: " << path;
    sets[path] = set;
  }
  return sets;
}

class StagedUpdateTest : public ::testing::Test {
 protected:
  StagedUpdateTest() {
    for (const char* id : {"boxes/start", "boxes/settled", "balls/start", "ramp/start"}) {
      write_pair(goldens_, id, "old");
    }
    write_pair(goldens_, "ramp/start@softpipe-1234", "baseline");
  }
  /// Stages the new set: every pair of boxes and balls, and a new scene folder.
  void stage_new_set(const StagedUpdate& update) const {
    for (const char* id : {"boxes/start", "boxes/settled", "balls/start", "cars/start"}) {
      write_pair(update.path(), id, "new");
    }
  }

  TempDir temp_;
  fs::path goldens_ = temp_.path() / "goldens";
};

TEST_F(StagedUpdateTest, CommitMovesTheWholeNewSetAndKeepsWhatItDoesNotReplace) {
  const auto before = files_of(goldens_);
  {
    StagedUpdate update(goldens_);
    stage_new_set(update);
    EXPECT_EQ(files_of(goldens_).size(), before.size() + 8) << "only the staging folder grew";
    EXPECT_EQ(update.commit(), 3u);
  }
  EXPECT_FALSE(fs::exists(goldens_ / kStagingFolderName));
  const auto sets = sets_of_pairs(goldens_);
  EXPECT_EQ(sets.at("boxes/start.png"), "new");
  EXPECT_EQ(sets.at("boxes/settled.png"), "new");
  EXPECT_EQ(sets.at("balls/start.png"), "new");
  EXPECT_EQ(sets.at("cars/start.png"), "new");
  EXPECT_EQ(sets.at("ramp/start.png"), "old");  // not part of the update
  EXPECT_EQ(sets.at("ramp/start@softpipe-1234.png"), "baseline");
}

TEST_F(StagedUpdateTest, FailureBetweenWritesLeavesTheOldSet) {
  const auto before = files_of(goldens_);
  try {
    StagedUpdate update(goldens_);
    write_pair(update.path(), "boxes/start", "new");
    image::write_text_file_atomically(update.path() / "boxes" / "settled.png", "png of new");
    throw std::runtime_error("injected: the disk filled up before settled.json");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(files_of(goldens_), before);
  EXPECT_FALSE(fs::exists(goldens_ / kStagingFolderName));
}

TEST_F(StagedUpdateTest, FailedSwapUndoesTheSwapsBeforeIt) {
  const auto before = files_of(goldens_);
  StagedUpdate update(goldens_);
  stage_new_set(update);
  int swaps = 0;
  EXPECT_THROW(update.commit([&](const std::string&) {
                 if (++swaps == 2) throw GoldenError("injected: the second swap failed");
               }),
               GoldenError);
  auto after = files_of(goldens_);
  for (auto it = after.begin(); it != after.end();) {
    it = it->first.rfind(kStagingFolderName, 0) == 0 ? after.erase(it) : std::next(it);
  }
  EXPECT_EQ(after, before);
}

TEST_F(StagedUpdateTest, ProcessKilledDuringTheCommitIsRolledForwardByTheNextRun) {
  const pid_t child = ::fork();
  if (child == 0) {
    StagedUpdate update(goldens_);
    stage_new_set(update);
    update.commit([](const std::string&) { ::_exit(0); });  // dies after the first swap
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  // Half-committed: each pair still whole (one scene folder new, the others old).
  int new_pairs = 0;
  for (const auto& [path, set] : sets_of_pairs(goldens_)) {
    if (path.rfind(kStagingFolderName, 0) != 0) new_pairs += set == "new" ? 1 : 0;
  }
  EXPECT_EQ(new_pairs, 1);  // balls/start: "balls" sorts first
  EXPECT_EQ(recover_interrupted_update(goldens_), Recovery::RolledForward);
  const auto sets = sets_of_pairs(goldens_);
  EXPECT_FALSE(fs::exists(goldens_ / kStagingFolderName));
  for (const char* png : {"boxes/start.png", "boxes/settled.png", "balls/start.png", "cars/start.png"}) {
    EXPECT_EQ(sets.at(png), "new") << png;
  }
  EXPECT_EQ(sets.at("ramp/start.png"), "old");
}

TEST_F(StagedUpdateTest, ProcessKilledBeforeTheCommitIsRolledBackByTheNextRun) {
  const auto before = files_of(goldens_);
  const pid_t child = ::fork();
  if (child == 0) {
    StagedUpdate update(goldens_);
    stage_new_set(update);
    ::_exit(0);  // as SIGKILL: no destructor runs
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(fs::exists(goldens_ / kStagingFolderName));
  EXPECT_NE(describe_interrupted_update(goldens_).find("would be removed"), std::string::npos);
  EXPECT_EQ(recover_interrupted_update(goldens_), Recovery::RolledBack);
  EXPECT_EQ(files_of(goldens_), before);
}

TEST_F(StagedUpdateTest, SecondUpdateOfTheSameFolderIsRefusedWhileTheFirstRuns) {
  StagedUpdate first(goldens_);
  EXPECT_EQ(recover_interrupted_update(goldens_), Recovery::Busy);
  const pid_t child = ::fork();
  if (child == 0) {
    try {
      StagedUpdate second(goldens_);
    } catch (const GoldenError&) {
      ::_exit(0);
    }
    ::_exit(1);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the second update was not refused";
}

TEST_F(StagedUpdateTest, UpdateThatCreatedTheGoldenFolderRemovesItWhenItFails) {
  const fs::path fresh = temp_.path() / "project" / "goldens";
  {
    StagedUpdate update(fresh);
    write_pair(update.path(), "boxes/start", "new");
  }
  EXPECT_FALSE(fs::exists(temp_.path() / "project"));
}

TEST(GoldenJson, FloatsAreWrittenInTheirShortestFloatFormAndReadBackExactly) {
  EXPECT_EQ(nlohmann::json(float_for_json(0.02f)).dump(), "0.02");
  EXPECT_EQ(nlohmann::json(float_for_json(11.23f)).dump(), "11.23");
  Sidecar sidecar;
  sidecar.scene = "boxes";
  sidecar.width = sidecar.height = 16;
  sidecar.bodies.push_back({"box", 11.23f, -0.1f, 0.7853982f});
  const nlohmann::json written = sidecar_to_json(sidecar);
  EXPECT_EQ(written["bodies"][0]["x"].dump(), "11.23");
  const Sidecar read = sidecar_from_json(written, "test");
  EXPECT_EQ(read.bodies[0].x, static_cast<double>(11.23f));
  EXPECT_EQ(read.bodies[0].y, static_cast<double>(-0.1f));
  EXPECT_EQ(read.bodies[0].angle, static_cast<double>(0.7853982f));
  // An older sidecar holds the float's exact double: it reads as the same float.
  nlohmann::json older = written;
  older["bodies"][0]["x"] = static_cast<double>(11.23f);
  EXPECT_EQ(sidecar_from_json(older, "test").bodies[0].x, static_cast<double>(11.23f));
}

TEST(GoldenJson, NonFiniteNumbersAreRefusedBeforeWriting) {
  TempDir temp;
  Sidecar sidecar;
  sidecar.scene = "boxes";
  sidecar.width = sidecar.height = 16;
  sidecar.tolerance.max_differing_ratio = std::numeric_limits<double>::quiet_NaN();
  const fs::path file = temp.path() / "boxes.json";
  try {
    write_sidecar(file, sidecar);
    FAIL() << "a NaN was written";
  } catch (const GoldenError& error) {
    EXPECT_NE(std::string(error.what()).find("tolerance.max_differing_ratio"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(file));
}

TEST(GoldenOutputPath, UnwritableOutputsAreFoundBeforeAnyWork) {
  TempDir temp;
  image::write_text_file_atomically(temp.path() / "notes.txt", "x");
  EXPECT_NO_THROW(check_output_path(temp.path() / "new" / "deeper" / "junit.xml", "--junit", false));
  EXPECT_THROW(check_output_path(temp.path() / "notes.txt" / "junit.xml", "--junit", false),
               GoldenError);
  EXPECT_THROW(check_output_path(temp.path(), "--junit", false), GoldenError);
  EXPECT_THROW(check_output_path(temp.path() / "notes.txt", "--report", true), GoldenError);
  EXPECT_FALSE(fs::exists(temp.path() / "new"));
}

}  // namespace
}  // namespace impulse2d::golden

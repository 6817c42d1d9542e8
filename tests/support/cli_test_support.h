#pragma once
// The `impulse2d` program run as a subprocess in a fresh directory per test: the fixture
// shared by the CLI test files (test_cli*.cpp).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cli_test {

namespace fs = std::filesystem;

/// Exit status and output of one run.
struct Result {
  int status = -1;   ///< exit status, -1 when killed by a signal
  std::string out;   ///< standard output
  std::string err;   ///< standard error
};

/// The whole file as bytes ("" when it cannot be read).
inline std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Writes `text` to `path`.
inline void write_file(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// A fresh, empty directory for one test (the process id keeps two suites running at once on
/// one machine, from two build trees, out of each other's way).
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("impulse2d_test_cli_" + std::string(info->name()) + "_" +
                                        std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Runs `impulse2d <arguments>` in the test directory; `environment` is prefixed (VAR=x).
  Result run(const std::string& arguments, const std::string& environment = "") const {
    const std::string command = "cd '" + dir_.string() + "' && " + environment +
                                " '" IMPULSE2D_CLI "' " + arguments + " > stdout.txt 2> stderr.txt";
    Result result;
    const int status = std::system(command.c_str());
    result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(dir_ / "stdout.txt");
    result.err = read_file(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return result;
  }

  /// Every file under the test directory.
  std::vector<std::string> files() const {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir_)) {
      if (entry.is_regular_file()) found.push_back(fs::relative(entry.path(), dir_).string());
    }
    return found;
  }

  fs::path dir_;  ///< the test's directory, removed afterwards
};

/// True when ffmpeg is on PATH (video tests skip without it).
inline bool have_ffmpeg() { return std::system("command -v ffmpeg > /dev/null 2>&1") == 0; }

}  // namespace cli_test

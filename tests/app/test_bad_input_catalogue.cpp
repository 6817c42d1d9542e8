// The bad-input catalogue (tests/app/bad_inputs/*.json): broken scene files, command lines,
// signals and write failures, each run through the impulse2d program in a fresh directory
// that already holds files. Each case states its exit status and the words its message must
// contain (the file, field or option, and the reason); a failing case must leave every file
// as it was and create none, and no case may leave files in its private $TMPDIR. Cases with
// exit status 0 are valid inputs that must stay accepted.
//
// catalogue.json holds `base_scene` and `existing` (shared by every file) and its cases; each
// other .json file of the folder holds `about` and `cases` of one area (golden, lab, ...).
// Keys of a case beyond the scene and file set-up:
//   args         the command line after `impulse2d` (a shell word list; quotes allowed)
//   environment  shell words before the program (e.g. `ulimit -f 8; trap '' XFSZ;` for a
//                write that fails once a file reaches 4 KiB, as on a full disk)
//   signal       {"name": "INT"|"TERM"|"HUP", "after_path": P, "after_ms": N}: the signal
//                is sent N ms after the path P (relative to the work folder, or to the
//                case's $TMPDIR when it starts with "$TMPDIR/") first exists (at once
//                without after_path)
//   files        "unchanged" (the default when exit != 0) or "any"
//   absent       substrings no path under the work folder may contain after the run
//   timeout_s    the program is killed (and the case fails) after this long (default 300)
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

/// The main catalogue: `base_scene`, `existing` files and `cases`.
const json& catalogue() {
  static const json document = json::parse(read_file(fs::path(IMPULSE2D_CATALOGUE_DIR) / "catalogue.json"));
  return document;
}

/// One case: its name, the file it comes from and its specification.
struct Case {
  std::string name;
  std::string file;
  json spec;
};

/// Every case of every .json file of the catalogue folder, files in name order.
std::vector<Case> cases() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(IMPULSE2D_CATALOGUE_DIR)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Case> result;
  for (const fs::path& file : files) {
    const json document = json::parse(read_file(file));
    for (const json& spec : document.at("cases")) {
      result.push_back(Case{spec.at("name").get<std::string>(), file.filename().string(), spec});
    }
  }
  return result;
}

/// The signal named in a case ("INT", "TERM", "HUP").
int signal_number(const std::string& name) {
  if (name == "INT") return SIGINT;
  if (name == "TERM") return SIGTERM;
  if (name == "HUP") return SIGHUP;
  ADD_FAILURE() << "unknown signal name " << name;
  return SIGTERM;
}

/// Runs `command` with /bin/sh (the last command `exec`s the program, so the shell's process
/// becomes the program's), sends the case's signal when due, and returns the wait status
/// (-1 when it had to be killed after `timeout`).
int run_case(const std::string& command, const json& spec, const fs::path& work, const fs::path& tmp,
             std::chrono::seconds timeout) {
  const pid_t child = fork();
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  using clock = std::chrono::steady_clock;
  const clock::time_point start = clock::now();
  std::optional<clock::time_point> signal_due;
  bool signalled = false;
  std::string after_path;
  if (spec.contains("signal")) {
    after_path = spec.at("signal").value("after_path", std::string());
    if (after_path.empty()) signal_due = start + std::chrono::milliseconds(spec.at("signal").value("after_ms", 0));
  }
  int status = 0;
  while (waitpid(child, &status, WNOHANG) == 0) {
    const clock::time_point now = clock::now();
    if (now - start > timeout) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      ADD_FAILURE() << "still running after " << timeout.count() << " s; killed";
      return -1;
    }
    if (!signalled && !signal_due && !after_path.empty()) {
      const std::string prefix = "$TMPDIR/";
      const fs::path watched = after_path.rfind(prefix, 0) == 0 ? tmp / after_path.substr(prefix.size())
                                                                : work / after_path;
      std::error_code error;
      if (fs::exists(watched, error)) {
        signal_due = now + std::chrono::milliseconds(spec.at("signal").value("after_ms", 0));
      }
    }
    if (!signalled && signal_due && now >= *signal_due) {
      kill(child, signal_number(spec.at("signal").at("name").get<std::string>()));
      signalled = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  if (spec.contains("signal") && !signalled) ADD_FAILURE() << "the program ended before the signal was due";
  return status;
}

/// The scene file of a case: `scene_text` verbatim, or `base_scene` with `set` (JSON pointer
/// -> value) and `remove` (JSON pointers) applied.
std::optional<std::string> scene_text(const json& spec) {
  if (spec.contains("scene_text")) return spec.at("scene_text").get<std::string>();
  if (!spec.contains("set") && !spec.contains("remove")) return std::nullopt;
  json scene = catalogue().at("base_scene");
  if (spec.contains("set")) {
    for (const auto& [pointer, value] : spec.at("set").items()) scene[json::json_pointer(pointer)] = value;
  }
  if (spec.contains("remove")) {
    for (const json& pointer : spec.at("remove")) {
      const json::json_pointer where(pointer.get<std::string>());
      scene[where.parent_pointer()].erase(where.back());
    }
  }
  return scene.dump(2);
}

/// Path -> contents of every file under `root` (directories as "<dir>").
std::map<std::string, std::string> snapshot(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const std::string name = fs::relative(entry.path(), root).string();
    files[name] = entry.is_symlink()     ? "<link to " + fs::read_symlink(entry.path()).string() + ">"
                  : entry.is_directory() ? "<dir>"
                                         : read_file(entry.path());
  }
  return files;
}

/// gtest prints a case by its name.
void PrintTo(const Case& each, std::ostream* out) { *out << each.file << ": " << each.name; }

class BadInputCatalogue : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputCatalogue, ExitStatusMessageAndNoFileChanged) {
  const json& spec = GetParam().spec;
  // The process id keeps suites of two build trees running at once apart.
  const fs::path root = fs::temp_directory_path() /
                        ("impulse2d_catalogue_" + GetParam().name + "_" + std::to_string(getpid()));
  const fs::path work = root / "work";
  const fs::path tmp = root / "tmp";
  fs::remove_all(root);
  fs::create_directories(work);
  fs::create_directories(tmp);
  for (const auto& [path, text] : catalogue().at("existing").items()) {
    write_file(work / path, text.get<std::string>());
  }
  if (spec.contains("existing")) {
    for (const auto& [path, text] : spec.at("existing").items()) {
      write_file(work / path, text.get<std::string>());
    }
  }
  if (spec.contains("existing_hex")) {
    for (const auto& [path, hex] : spec.at("existing_hex").items()) {
      std::string bytes;
      const std::string digits = hex.get<std::string>();
      for (std::size_t i = 0; i + 1 < digits.size(); i += 2) {
        bytes.push_back(static_cast<char>(std::stoi(digits.substr(i, 2), nullptr, 16)));
      }
      write_file(work / path, bytes);
    }
  }
  if (spec.contains("existing_size")) {
    for (const auto& [path, size] : spec.at("existing_size").items()) {
      write_file(work / path, std::string(size.get<std::size_t>(), ' '));
    }
  }
  if (spec.contains("symlinks")) {
    for (const auto& [path, target] : spec.at("symlinks").items()) {
      fs::create_symlink(target.get<std::string>(), work / path);
    }
  }
  if (const std::optional<std::string> text = scene_text(spec)) write_file(work / "scene.json", *text);
  const std::map<std::string, std::string> before = snapshot(work);

  const std::string command = "cd '" + work.string() + "' && export TMPDIR='" + tmp.string() + "' && " +
                              spec.value("environment", std::string()) + " exec '" IMPULSE2D_CLI "' " +
                              spec.at("args").get<std::string>() + " > '" +
                              spec.value("stdout", (root / "stdout").string()) + "' 2> '" + (root / "stderr").string() +
                              "' < /dev/null";
  const int status = run_case(command, spec, work, tmp, std::chrono::seconds(spec.value("timeout_s", 300)));
  // A program killed by signal N reports it as the shell would: 128 + N.
  const int exit_status = status == -1         ? -1
                          : WIFEXITED(status)   ? WEXITSTATUS(status)
                          : WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                                : -1;
  const std::string err = read_file(root / "stderr");
  const std::string out = read_file(root / "stdout");

  const int expected = spec.at("exit").get<int>();
  EXPECT_EQ(exit_status, expected) << spec.at("args") << "\nstderr: " << err;
  const std::string& message_stream = spec.value("stream", std::string("stderr")) == "stdout" ? out : err;
  for (const json& word : spec.value("message", json::array())) {
    EXPECT_NE(message_stream.find(word.get<std::string>()), std::string::npos)
        << "message lacks \"" << word.get<std::string>() << "\": " << message_stream;
  }
  if (spec.value("files", std::string(expected != 0 ? "unchanged" : "any")) == "unchanged") {
    EXPECT_EQ(snapshot(work), before) << "a failed run created or changed files";
  }
  for (const json& word : spec.value("absent", json::array())) {
    for (const auto& [path, contents] : snapshot(work)) {
      EXPECT_EQ(path.find(word.get<std::string>()), std::string::npos) << "left behind: " << path;
    }
  }
  for (const auto& [path, contents] : snapshot(tmp)) ADD_FAILURE() << "left in $TMPDIR: " << path;
  fs::remove_all(root);
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInputCatalogue, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& param_info) { return param_info.param.name; });

TEST(BadInputCatalogueShape, HoldsAtLeastSixtyFailingCasesWithUniqueNames) {
  std::set<std::string> names;
  int failing = 0;
  for (const Case& each : cases()) {
    EXPECT_TRUE(names.insert(each.name).second) << "duplicate case name " << each.name;
    if (each.spec.at("exit").get<int>() != 0) {
      ++failing;
      EXPECT_FALSE(each.spec.value("message", json::array()).empty())
          << each.name << ": a failing case must say what its message names";
    }
  }
  EXPECT_GE(failing, 60);
}

}  // namespace

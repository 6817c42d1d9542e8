// The bad-input catalogue (tests/bad_inputs/catalogue.json): broken scene files and command
// lines, each run through the impulse2d program in a fresh directory that already holds
// files. Each case states its exit status and the words its message must contain (the file,
// field or option, and the reason); a failing case must leave every file as it was and
// create none. Cases with exit status 0 are valid inputs that must stay accepted.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
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

/// The catalogue: `base_scene`, `existing` files and `cases`.
const json& catalogue() {
  static const json document = json::parse(read_file(IMPULSE2D_CATALOGUE));
  return document;
}

/// One case, expanded: the scene file text (if any) and the command line.
struct Case {
  std::string name;
  json spec;
};

std::vector<Case> cases() {
  std::vector<Case> result;
  for (const json& spec : catalogue().at("cases")) {
    result.push_back(Case{spec.at("name").get<std::string>(), spec});
  }
  return result;
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
void PrintTo(const Case& each, std::ostream* out) { *out << each.name; }

class BadInputCatalogue : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputCatalogue, ExitStatusMessageAndNoFileChanged) {
  const json& spec = GetParam().spec;
  // The process id keeps suites of two build trees running at once apart.
  const fs::path root = fs::temp_directory_path() /
                        ("impulse2d_catalogue_" + GetParam().name + "_" + std::to_string(getpid()));
  const fs::path work = root / "work";
  fs::remove_all(root);
  fs::create_directories(work);
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

  const std::string command = "cd '" + work.string() + "' && " +
                              spec.value("environment", std::string()) + " '" IMPULSE2D_CLI "' " +
                              spec.at("args").get<std::string>() + " > '" +
                              spec.value("stdout", (root / "stdout").string()) + "' 2> '" + (root / "stderr").string() +
                              "' < /dev/null";
  const int status = std::system(command.c_str());
  const int exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  const std::string err = read_file(root / "stderr");
  const std::string out = read_file(root / "stdout");

  const int expected = spec.at("exit").get<int>();
  EXPECT_EQ(exit_status, expected) << spec.at("args") << "\nstderr: " << err;
  const std::string& message_stream = spec.value("stream", std::string("stderr")) == "stdout" ? out : err;
  for (const json& word : spec.value("message", json::array())) {
    EXPECT_NE(message_stream.find(word.get<std::string>()), std::string::npos)
        << "message lacks \"" << word.get<std::string>() << "\": " << message_stream;
  }
  if (expected != 0) {
    EXPECT_EQ(snapshot(work), before) << "a failed run created or changed files";
  }
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

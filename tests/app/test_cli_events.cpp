// `impulse2d trace --events`, `--save-state` and `--load-state` run as a subprocess (issue 32).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Output {
  int exit = -1;
  std::string out;
  std::string err;
};

std::string slurp(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Runs `impulse2d <args>` in `folder` (args are shell words).
Output run_cli(const fs::path& folder, const std::string& args) {
  const std::string command = "cd '" + folder.string() + "' && '" IMPULSE2D_CLI "' " + args +
                              " > stdout.txt 2> stderr.txt";
  const int status = std::system(command.c_str());
  Output result;
  result.exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = slurp(folder / "stdout.txt");
  result.err = slurp(folder / "stderr.txt");
  return result;
}

fs::path fresh_folder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() /
                          ("impulse2d_events_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  for (const char c : line) {
    if (c == ',') {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

/// A ball (radius 0.5, its bottom `drop` m above the ground) falling onto static ground.
std::string drop_scene(double drop) {
  return R"({"name": "drop", "settings": {"gravity": [0, -10], "time_step": 0.0166666675,
    "hit_event_speed": 1.0},
    "bodies": [
      {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [10, 0.5]},
       "position": [0, -0.5]},
      {"name": "ball", "shape": {"type": "circle", "radius": 0.5}, "position": [0, )" +
         std::to_string(drop + 0.5) + R"(], "material": "Rock", "events": {"hit": true}}],
    "run": {"steps": 120}})";
}

}  // namespace

TEST(TraceEvents, ABallDroppedOnTheGroundBeginsTouchingAndHitsOnceAtTheSameStep) {
  const fs::path folder = fresh_folder("drop");
  const double drop = 5.0, gravity = 10.0;
  std::ofstream(folder / "drop.json") << drop_scene(drop);
  const Output result = run_cli(folder, "trace drop.json --events --steps 75");
  ASSERT_EQ(result.exit, 0) << result.err;
  const std::vector<std::string> lines = lines_of(result.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "step,kind,shape_a,shape_b,body_a,body_b,x,y,nx,ny,speed");
  int begins = 0, hits = 0;
  std::string begin_step, hit_step;
  double speed = 0.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> fields = fields_of(lines[i]);
    ASSERT_EQ(fields.size(), 11u) << lines[i];
    if (fields[1] == "begin_touch") {
      ++begins;
      begin_step = fields[0];
      EXPECT_EQ(fields[4], "0");
      EXPECT_EQ(fields[5], "1");
      EXPECT_EQ(fields[6], "") << "a begin has no point";
    } else if (fields[1] == "hit") {
      ++hits;
      hit_step = fields[0];
      EXPECT_EQ(fields[4], "0");
      EXPECT_EQ(fields[5], "1");
      EXPECT_NEAR(std::stod(fields[9]), 1.0, 1e-6) << "normal from the ground (A) up to the ball";
      speed = std::stod(fields[10]);
    }
  }
  EXPECT_EQ(begins, 1) << result.out;
  EXPECT_EQ(hits, 1) << result.out;
  EXPECT_EQ(begin_step, hit_step);
  const double expected = std::sqrt(2.0 * gravity * drop);
  EXPECT_NEAR(speed, expected, 0.01 * expected);

  // The same events as JSON.
  const Output json = run_cli(folder, "trace drop.json --events --steps 75 --format json");
  ASSERT_EQ(json.exit, 0) << json.err;
  const nlohmann::json document = nlohmann::json::parse(json.out);
  int json_hits = 0;
  for (const nlohmann::json& event : document.at("events")) {
    if (event.at("kind") == "hit") {
      ++json_hits;
      EXPECT_EQ(std::to_string(event.at("step").get<int>()), hit_step);
      EXPECT_FLOAT_EQ(event.at("speed").get<float>(), static_cast<float>(speed));
    } else {
      EXPECT_FALSE(event.contains("x")) << event.dump();
    }
  }
  EXPECT_EQ(json_hits, 1);
  fs::remove_all(folder);
}

TEST(TraceState, SavingAfterNStepsAndLoadingForNMoreEqualsTwoNSteps) {
  const fs::path folder = fresh_folder("state");
  for (const std::string scene : {"pyramid", "drop.json"}) {
    std::ofstream(folder / "drop.json") << drop_scene(1.0);
    const Output whole = run_cli(folder, "trace " + scene + " --steps 80");
    ASSERT_EQ(whole.exit, 0) << whole.err;
    const Output first = run_cli(folder, "trace " + scene + " --steps 40 --save-state s.state");
    ASSERT_EQ(first.exit, 0) << first.err;
    ASSERT_TRUE(fs::exists(folder / "s.state"));
    const Output second = run_cli(folder, "trace " + scene + " --steps 40 --load-state s.state");
    ASSERT_EQ(second.exit, 0) << second.err;
    // Every row of the resumed run (steps 40..80) is the whole run's row, bit for bit.
    const std::vector<std::string> all = lines_of(whole.out), resumed = lines_of(second.out);
    ASSERT_GT(resumed.size(), 2u);
    ASSERT_LE(resumed.size(), all.size());
    for (std::size_t i = 1; i <= resumed.size() - 1; ++i) {
      EXPECT_EQ(resumed[resumed.size() - i], all[all.size() - i]) << scene;
    }
    EXPECT_EQ(fields_of(resumed[1])[0], "40");
  }
  fs::remove_all(folder);
}

// Every built-in scene, 60 steps in one process against 30, saved, and 30 more in a fresh
// process: the frame at step 60 is the same PNG, byte for byte (its pixels and its metadata,
// which holds the state hash). The scripted scenes (tutorial, push, platformer, mouse_drag)
// save their script's state with the world and are resumed like the others.
TEST(TraceState, EveryBuiltInSceneResumedInAFreshProcessDrawsTheSameFrame) {
  const fs::path folder = fresh_folder("every");
  const Output list = run_cli(folder, "list");
  ASSERT_EQ(list.exit, 0) << list.err;
  std::vector<std::string> scenes;
  for (const std::string& line : lines_of(list.out)) {
    if (!line.empty() && line.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") == std::string::npos) {
      scenes.push_back(line);
    }
  }
  ASSERT_GE(scenes.size(), 20u) << list.out;
  for (const char* scripted : {"tutorial", "push", "platformer", "mouse_drag"}) {
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), scripted), scenes.end()) << scripted;
  }
  std::vector<std::string> compared;
  for (const std::string& scene : scenes) {
    const std::string size = " --size 160x120 --quiet";
    const Output whole = run_cli(folder, "render " + scene + " --frames 60 -o whole_" + scene + size);
    ASSERT_EQ(whole.exit, 0) << scene << ": " << whole.err;
    const Output save = run_cli(folder, "trace " + scene + " --steps 30 --save-state " + scene + ".state");
    ASSERT_EQ(save.exit, 0) << scene << ": " << save.err;
    const Output load = run_cli(folder, "render " + scene + " --load-state " + scene + ".state --frames 60 -o resumed_" +
                                            scene + size);
    ASSERT_EQ(load.exit, 0) << scene << ": " << load.err;
    const std::string frame = "/" + scene + "_00000.png";
    const std::string expected = slurp(folder / ("whole_" + scene + frame));
    ASSERT_FALSE(expected.empty()) << scene;
    EXPECT_EQ(expected, slurp(folder / ("resumed_" + scene + frame)))
        << scene << ": the resumed run draws another frame at step 60";
    compared.push_back(scene);
  }
  std::printf("%zu built-in scenes resumed bit for bit, the 4 scripted ones included\n", compared.size());
  EXPECT_EQ(compared.size(), scenes.size());
  fs::remove_all(folder);
}

TEST(TraceState, AStateOfAnotherSceneOrACorruptFileIsRefusedWithExitTwo) {
  const fs::path folder = fresh_folder("refuse");
  ASSERT_EQ(run_cli(folder, "trace pyramid --steps 5 --save-state p.state").exit, 0);
  const Output other = run_cli(folder, "trace ball_pit --steps 5 --load-state p.state");
  EXPECT_EQ(other.exit, 2);
  EXPECT_NE(other.err.find("p.state"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("pyramid"), std::string::npos) << other.err;

  std::string bytes = slurp(folder / "p.state");
  ASSERT_GT(bytes.size(), 100u);
  for (const std::size_t at : {std::size_t{8}, std::size_t{12}, std::size_t{40}, bytes.size() / 2, bytes.size() - 1}) {
    std::string changed = bytes;
    changed[at] = static_cast<char>(changed[at] ^ 0x5a);
    std::ofstream(folder / "bad.state", std::ios::binary) << changed;
    const Output bad = run_cli(folder, "trace pyramid --steps 5 --load-state bad.state");
    EXPECT_EQ(bad.exit, 2) << "byte " << at << ": " << bad.err;
    EXPECT_NE(bad.err.find("bad.state"), std::string::npos) << bad.err;
  }
  std::ofstream(folder / "short.state", std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  const Output truncated = run_cli(folder, "trace pyramid --steps 5 --load-state short.state");
  EXPECT_EQ(truncated.exit, 2);
  EXPECT_NE(truncated.err.find("short.state"), std::string::npos) << truncated.err;
  const Output missing = run_cli(folder, "trace pyramid --steps 5 --load-state nowhere.state");
  EXPECT_EQ(missing.exit, 2);
  EXPECT_NE(missing.err.find("nowhere.state"), std::string::npos) << missing.err;
  fs::remove_all(folder);
}

// A scripted scene's state file ends with its script's section (u64 byte count, u64 hash, the
// bytes): a changed byte there, a wrong count, a missing section or other script parameters
// are refused with exit 2 naming the file and the reason, never resumed.
TEST(TraceState, ACorruptScriptSectionOrOtherScriptParametersAreRefused) {
  const fs::path folder = fresh_folder("script");
  ASSERT_EQ(run_cli(folder, "trace tutorial --steps 40 --save-state t.state").exit, 0);
  const std::string bytes = slurp(folder / "t.state");
  // tutorial's script state: u32 version + i32 bodies dropped = 8 bytes, after count and hash.
  const std::size_t script_at = bytes.size() - 8;
  const std::size_t count_at = script_at - 16;
  ASSERT_EQ(static_cast<unsigned char>(bytes[count_at]), 8u);
  const struct {
    const char* what;
    std::string bytes;
    const char* says;
  } cases[] = {
      {"a script byte changed", bytes.substr(0, script_at + 4) + std::string(1, static_cast<char>(bytes[script_at + 4] ^ 0x01)) +
                                    bytes.substr(script_at + 5),
       "script's state is corrupt"},
      {"a hash byte changed", bytes.substr(0, count_at + 8) + std::string(1, static_cast<char>(bytes[count_at + 8] ^ 0x40)) +
                                  bytes.substr(count_at + 9),
       "script's state is corrupt"},
      {"the count too large", bytes.substr(0, count_at) + std::string(1, '\x09') + bytes.substr(count_at + 1),
       "ends inside the script's state"},
      {"the count too small", bytes.substr(0, count_at) + std::string(1, '\x07') + bytes.substr(count_at + 1),
       "bytes after the script's state"},
      {"the section cut off", bytes.substr(0, count_at + 4), "ends inside the script state's size"},
  };
  for (const auto& each : cases) {
    std::ofstream(folder / "bad.state", std::ios::binary) << each.bytes;
    const Output bad = run_cli(folder, "trace tutorial --steps 5 --load-state bad.state");
    EXPECT_EQ(bad.exit, 2) << each.what << ": " << bad.err;
    EXPECT_NE(bad.err.find("bad.state"), std::string::npos) << each.what << ": " << bad.err;
    EXPECT_NE(bad.err.find(each.says), std::string::npos) << each.what << ": " << bad.err;
    EXPECT_TRUE(bad.out.empty()) << each.what << ": nothing is traced";
  }
  // The seed only the script reads: its state would continue another rain.
  const Output seed = run_cli(folder, "trace tutorial --param seed=2 --steps 5 --load-state t.state");
  EXPECT_EQ(seed.exit, 2) << seed.err;
  EXPECT_NE(seed.err.find("other --param values"), std::string::npos) << seed.err;
  // The unchanged file still loads.
  EXPECT_EQ(run_cli(folder, "trace tutorial --steps 5 --load-state t.state").exit, 0);
  fs::remove_all(folder);
}

namespace {

/// Three boxes stacked on static ground and a ball dropped beside them, with two goldens of
/// 96x72: "start" (step 0) and "settled" (step 90).
std::string stack_scene_with_goldens() {
  return R"({"name": "stack", "settings": {"gravity": [0, -10], "time_step": 0.0166666675},
    "bodies": [
      {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [6, 0.5]},
       "position": [0, -0.5]},
      {"name": "low", "shape": {"type": "box", "half_extents": [0.5, 0.5]}, "position": [0, 0.5]},
      {"name": "middle", "shape": {"type": "box", "half_extents": [0.5, 0.5]}, "position": [0.1, 1.6]},
      {"name": "top", "shape": {"type": "box", "half_extents": [0.5, 0.5]}, "position": [-0.1, 2.7]},
      {"name": "ball", "shape": {"type": "circle", "radius": 0.4}, "position": [1.5, 4],
       "material": "Rock"}],
    "run": {"steps": 120},
    "golden": {"size": [96, 72], "frames": [{"name": "start", "step": 0},
                                            {"name": "settled", "step": 90}]}})";
}

}  // namespace

// `golden frame --load-state`, as `render --load-state`: the golden's step stays its own, so a
// state saved after N steps and resumed in a fresh process draws the golden at step S (N + M,
// M = S - N steps after the saved one) exactly as a run from the start: the same PNG bytes
// (pixels and metadata) and the same state hash in PNG.hash.
TEST(GoldenFrameState, ResumedFromAStateSavedMidRunDrawsTheSameFrameAndHash) {
  const fs::path folder = fresh_folder("golden");
  std::ofstream(folder / "stack.json") << stack_scene_with_goldens();
  const Output whole = run_cli(folder, "golden frame stack.json settled --out whole.png");
  ASSERT_EQ(whole.exit, 0) << whole.err;
  for (const int saved : {0, 40, 90}) {
    const std::string state = "s" + std::to_string(saved) + ".state";
    const Output save =
        run_cli(folder, "trace stack.json --steps " + std::to_string(saved) + " --save-state " + state);
    ASSERT_EQ(save.exit, 0) << save.err;
    const std::string png = "resumed" + std::to_string(saved) + ".png";
    const Output load =
        run_cli(folder, "golden frame stack.json settled --load-state " + state + " --out " + png);
    ASSERT_EQ(load.exit, 0) << saved << ": " << load.err;
    const std::string expected = slurp(folder / "whole.png");
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(slurp(folder / png), expected) << "saved after " << saved << " steps";
    const std::string hash = slurp(folder / "whole.png.hash");
    ASSERT_FALSE(hash.empty());
    EXPECT_EQ(slurp(folder / (png + ".hash")), hash) << "saved after " << saved << " steps";
  }
  fs::remove_all(folder);
}

// A state the golden cannot be drawn from is refused with exit 2 before anything is written,
// by the run and by --dry-run alike: one of another scene, a corrupt one, one saved after the
// golden's step.
TEST(GoldenFrameState, AStateOfAnotherSceneCorruptOrSavedAfterTheFrameIsRefusedWithExitTwo) {
  const fs::path folder = fresh_folder("golden_refuse");
  std::ofstream(folder / "stack.json") << stack_scene_with_goldens();
  std::ofstream(folder / "drop.json") << drop_scene(1.0);
  ASSERT_EQ(run_cli(folder, "trace drop.json --steps 5 --save-state drop.state").exit, 0);
  ASSERT_EQ(run_cli(folder, "trace stack.json --steps 30 --save-state late.state").exit, 0);
  std::string bytes = slurp(folder / "late.state");
  ASSERT_GT(bytes.size(), 100u);
  bytes[bytes.size() / 2] = static_cast<char>(bytes[bytes.size() / 2] ^ 0x5a);
  std::ofstream(folder / "bad.state", std::ios::binary) << bytes;
  struct Refusal {
    std::string frame, state, says;
  };
  for (const Refusal& refusal : {Refusal{"settled", "drop.state", "'drop'"},
                                 Refusal{"settled", "bad.state", "bad.state"},
                                 Refusal{"start", "late.state", "saved after 30 steps"}}) {
    for (const std::string dry_run : {"", "--dry-run "}) {
      const Output refused = run_cli(folder, dry_run + "golden frame stack.json " + refusal.frame +
                                                 " --load-state " + refusal.state + " --out f.png");
      EXPECT_EQ(refused.exit, 2) << dry_run << refusal.state << ": " << refused.err;
      EXPECT_NE(refused.err.find(refusal.state), std::string::npos) << refused.err;
      EXPECT_NE(refused.err.find(refusal.says), std::string::npos) << refused.err;
      EXPECT_FALSE(fs::exists(folder / "f.png")) << refusal.state;
      EXPECT_FALSE(fs::exists(folder / "f.png.hash")) << refusal.state;
    }
  }
  fs::remove_all(folder);
}

// The scripted built-in scenes saved mid-run (world snapshot + script state) and continued by a
// fresh run: bit for bit as the run that saved them, at moments chosen to catch each script's
// state (issue 32); and a rollback: the same saved state continued with other input and again
// with the first.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "core/world.h"
#include "demos/scene_registry.h"
#include "scene/scene_run.h"
#include "scene/usage_error.h"

using namespace impulse2d;
using namespace impulse2d::demos;

namespace {

/// A run's world and script state at one moment.
struct Saved {
  std::vector<std::uint8_t> world;
  std::vector<std::uint8_t> script;
};

Saved save(const SceneRun& run) { return Saved{run.world().save_snapshot(), run.save_script_state()}; }

void step_to(SceneRun& run, std::int64_t step) {
  while (run.step_count() < step) run.step();
}

const Scene& builtin(const std::string& name) {
  const Scene* scene = find_builtin_scene(name);
  if (scene == nullptr) throw std::runtime_error("no built-in scene " + name);
  return *scene;
}

/// A button press (or release) at `step`, as the platformer's own events are written.
SceneEvent press(std::int64_t step, const std::string& button, bool pressed) {
  SceneEvent event;
  event.step = step;
  event.kind = SceneEventKind::Button;
  event.button = button;
  event.pressed = pressed;
  event.origin = "test input";
  return event;
}

}  // namespace

// Saved at step N and continued M steps in a fresh run, each scripted scene ends in the same
// world bytes (bodies, contacts, joints, time) and the same script state as the run that went
// on. The moments: tutorial just after a drop and after bodies fell off and were removed;
// platformer on the ground, rising through the one-way platform, dropping through it, in the
// coyote window, mid double jump, on the moving platform and between wall jumps.
TEST(ScriptState, ScriptedScenesContinueBitForBitFromASavedState) {
  struct Moment {
    const char* scene;
    std::int64_t at;
    std::int64_t then;
  };
  const Moment moments[] = {
      {"tutorial", 37, 60},    {"tutorial", 400, 200},  {"push", 50, 40},
      {"mouse_drag", 100, 80}, {"platformer", 0, 30},   {"platformer", 30, 60},
      {"platformer", 140, 40}, {"platformer", 201, 30}, {"platformer", 450, 40},
      {"platformer", 474, 30}, {"platformer", 700, 60}, {"platformer", 995, 30},
  };
  for (const Moment& moment : moments) {
    const Scene& scene = builtin(moment.scene);
    const Params params(scene.params);
    SceneRun whole(scene, params);
    step_to(whole, moment.at);
    const Saved saved = save(whole);
    step_to(whole, moment.at + moment.then);

    SceneRun resumed(scene, params);
    resumed.restore_snapshot(saved.world, saved.script);
    EXPECT_TRUE(resumed.restored());
    EXPECT_EQ(resumed.step_count(), moment.at);
    step_to(resumed, moment.at + moment.then);
    const std::string where = std::string(moment.scene) + " saved at " + std::to_string(moment.at);
    EXPECT_EQ(resumed.world().state_hash(), whole.world().state_hash()) << where;
    EXPECT_TRUE(resumed.world().save_snapshot() == whole.world().save_snapshot()) << where;
    EXPECT_TRUE(resumed.save_script_state() == whole.save_script_state()) << where;
    EXPECT_EQ(resumed.followed_position().has_value(), whole.followed_position().has_value()) << where;
  }
}

// Rollback: the platformer saved at step 300, run 10 steps with input A (walk left), restored
// and run with input B (jump), restored again (into the run that took A) and run with A: the
// second A ends exactly where the first did, and B somewhere else.
TEST(ScriptState, RollbackWithOtherInputAndBackGivesTheFirstResult) {
  Scene with_a = builtin("platformer");
  with_a.events.push_back(press(300, "left", true));
  Scene with_b = builtin("platformer");
  with_b.events.push_back(press(300, "jump", true));
  const Params params(with_a.params);

  SceneRun run_a(with_a, params);
  step_to(run_a, 300);
  const Saved saved = save(run_a);
  step_to(run_a, 310);
  const std::vector<std::uint8_t> first_a = run_a.world().save_snapshot();
  const std::vector<std::uint8_t> first_a_script = run_a.save_script_state();

  SceneRun run_b(with_b, params);
  run_b.restore_snapshot(saved.world, saved.script);
  step_to(run_b, 310);
  EXPECT_NE(run_b.world().state_hash(), run_a.world().state_hash()) << "input B changes the run";

  run_a.restore_snapshot(saved.world, saved.script);  // rolled back: a run that stepped past it
  EXPECT_EQ(run_a.step_count(), 300);
  step_to(run_a, 310);
  EXPECT_TRUE(run_a.world().save_snapshot() == first_a);
  EXPECT_TRUE(run_a.save_script_state() == first_a_script);
}

// A script state that does not fit is refused with `Error` naming the script and the byte, and
// the run keeps its state: another scene's, truncated, another version, a flag that is not a
// bool, none for a scripted scene, one for a scene without a script.
TEST(ScriptState, BytesThatDoNotFitAreRefusedAndTheRunKeepsItsState) {
  const Scene& scene = builtin("platformer");
  const Params params(scene.params);
  SceneRun source(scene, params);
  step_to(source, 50);
  const Saved saved = save(source);
  SceneRun tutorial_run(builtin("tutorial"), Params(builtin("tutorial").params));
  step_to(tutorial_run, 30);
  const std::vector<std::uint8_t> tutorial_script = tutorial_run.save_script_state();

  std::vector<std::uint8_t> truncated = saved.script;
  truncated.resize(truncated.size() - 3);
  std::vector<std::uint8_t> other_version = saved.script;
  other_version[0] = 9;
  std::vector<std::uint8_t> not_a_bool = saved.script;
  // platformer: u32 version, body (8), f32 direction, u32 nested size; then the character
  // script's u32 version and its first button flag.
  not_a_bool[4 + 8 + 4 + 4 + 4] = 7;
  const struct {
    const char* what;
    std::vector<std::uint8_t> bytes;
    const char* says;
  } cases[] = {
      {"another scene's", tutorial_script, "ends early"},
      {"truncated", truncated, "ends early"},
      {"another version", other_version, "layout version 9"},
      {"not a bool", not_a_bool, "out of range 0..1"},
      {"none", {}, "no state of the scene's script"},
  };
  for (const auto& each : cases) {
    SceneRun run(scene, params);
    step_to(run, 5);
    const std::vector<std::uint8_t> before = run.world().save_snapshot();
    const std::vector<std::uint8_t> before_script = run.save_script_state();
    try {
      run.restore_snapshot(saved.world, each.bytes);
      ADD_FAILURE() << each.what << ": accepted";
    } catch (const UsageError& error) {
      ADD_FAILURE() << each.what << ": a usage error, not a refused state: " << error.what();
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(each.says), std::string::npos) << each.what << ": " << error.what();
    }
    EXPECT_FALSE(run.restored()) << each.what;
    EXPECT_TRUE(run.world().save_snapshot() == before) << each.what;
    EXPECT_TRUE(run.save_script_state() == before_script) << each.what;
  }

  SceneRun pyramid(builtin("pyramid"), Params(builtin("pyramid").params));
  const std::vector<std::uint8_t> pyramid_world = pyramid.world().save_snapshot();
  EXPECT_THROW(pyramid.restore_snapshot(pyramid_world, saved.script), Error);
  EXPECT_NO_THROW(pyramid.restore_snapshot(pyramid_world, {}));
}

// The `platformer` demo's scripted run still shows every move: the character is where each
// move leaves it at the step the script expects (so a change in the engine or the controller
// that breaks the demo fails here, not only in a golden image).
#include "demos/scene_registry.h"
#include "scene/scene_run.h"

#include <gtest/gtest.h>

#include <map>

using namespace impulse2d;
using namespace impulse2d::demos;

namespace {

struct Checkpoint {
  const char* move;
  vec2 lower;  // the character's centre lies in [lower, upper], metres
  vec2 upper;
};

}  // namespace

TEST(PlatformerScene, ScriptedRunReachesEveryCheckpoint) {
  const Scene* found = find_builtin_scene("platformer");
  ASSERT_NE(found, nullptr);
  const Scene& scene = *found;
  SceneRun run(scene, Params(scene.params));
  // Steps at 60 Hz, from the scene's script; floor top 0, one-way top 2.2, slope 30 degrees
  // from x = 7, ledge top 3.6, shaft block top 6.3; the character is 1 m tall.
  const std::map<std::int64_t, Checkpoint> checkpoints = {
      {40, {"hop apex about h = 1.2 m up", {-1.6f, 1.6f}, {-1.4f, 1.75f}}},
      {150, {"rising through the one-way platform", {2.6f, 2.0f}, {2.9f, 2.3f}}},
      {190, {"standing on the one-way platform", {2.6f, 2.68f}, {2.9f, 2.7f}}},
      {240, {"dropped through onto the floor", {2.6f, 0.48f}, {2.9f, 0.5f}}},
      {370, {"idle on the slope", {9.0f, 1.8f}, {10.0f, 2.4f}}},
      {486, {"coyote jump then double jump", {18.5f, 5.0f}, {19.5f, 6.5f}}},
      {556, {"buffered hop off the ledge", {19.0f, 4.2f}, {19.4f, 5.5f}}},
      {760, {"riding the moving platform", {22.5f, 4.08f}, {27.5f, 4.1f}}},
      {1000, {"wall jump in the shaft", {34.0f, 1.0f}, {36.5f, 6.0f}}},
      {1109, {"on top of the shaft block", {36.6f, 6.78f}, {39.7f, 6.8f}}},
  };
  BodyId character;
  while (run.step_count() < scene.view.steps) {
    run.step();
    if (character.is_null()) {
      for (const BodyId id : run.world().body_ids()) {
        if (run.world().body(id).type == BodyType::Dynamic) character = id;
      }
    }
    const auto checkpoint = checkpoints.find(run.step_count() - 1);
    if (checkpoint == checkpoints.end()) continue;
    const vec2 at = run.world().body(character).transform.position;
    const Checkpoint& expected = checkpoint->second;
    EXPECT_TRUE(at.x >= expected.lower.x && at.x <= expected.upper.x && at.y >= expected.lower.y &&
                at.y <= expected.upper.y)
        << expected.move << " at step " << checkpoint->first << ": character at (" << at.x << ", "
        << at.y << ")";
  }
}

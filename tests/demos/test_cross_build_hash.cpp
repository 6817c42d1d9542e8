// Determinism across machines and compilers: long runs of built-in scenes end in a pinned
// state hash. The same test runs in the GCC build and in the Clang (sanitizer) build of
// scripts/test.sh, so both compilers must produce these bits; the state never goes through
// libm (core/trig.h), so any IEEE-754 x86-64 or AArch64 build with the same flags agrees.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "scene/params.h"
#include "demos/scene_registry.h"
#include "scene/scene_run.h"

namespace impulse2d::demos {
namespace {

std::uint64_t final_hash(const std::string& name, std::int64_t steps) {
  const Scene* scene = find_builtin_scene(name);
  if (scene == nullptr) throw std::runtime_error("no scene " + name);
  SceneRun run(*scene, Params(scene->params));
  while (run.step_count() < steps) run.step();
  return run.world().state_hash();
}

std::string hex(std::uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

TEST(CrossBuildHash, LongRunsEndInThePinnedState) {
  // scene, steps, final state hash (pinned from a GCC 12 build; Clang 14 must agree).
  const struct {
    const char* scene;
    std::int64_t steps;
    const char* hash;
  } runs[] = {{"tutorial", 900, "cfe2c2bd7936f8fb"},
              {"random_polygons", 900, "52b2e32ecad07187"},
              {"pyramid", 900, "e2d2e1c8d83b24be"},
              {"friction_ramp", 600, "cf8dfeba4258991d"}};
  for (const auto& each : runs) {
    EXPECT_EQ(hex(final_hash(each.scene, each.steps)), each.hash) << each.scene;
  }
}

}  // namespace
}  // namespace impulse2d::demos

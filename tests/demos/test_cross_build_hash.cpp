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

// FNV-1a over raw bytes.
void mix(std::uint64_t& hash, const void* data, std::size_t size) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= bytes[i];
    hash *= 1099511628211ull;
  }
}

void mix_ids(std::uint64_t& hash, BodyId a, BodyId b) {
  const std::uint32_t ids[4] = {a.index, a.generation, b.index, b.generation};
  mix(hash, ids, sizeof ids);
}

// A hash of every event of every step of a run: kind, step, bodies and a hit's point, normal
// and speed (their bits).
std::uint64_t events_hash(const std::string& name, std::int64_t steps) {
  const Scene* scene = find_builtin_scene(name);
  if (scene == nullptr) throw std::runtime_error("no scene " + name);
  SceneRun run(*scene, Params(scene->params));
  std::uint64_t hash = 14695981039346656037ull;
  std::uint64_t count = 0;
  while (run.step_count() < steps) {
    run.step();
    const std::int64_t step = run.step_count();
    const ContactEvents& contacts = run.world().contact_events();
    const SensorEvents& sensors = run.world().sensor_events();
    const auto record = [&](char kind, BodyId a, BodyId b) {
      mix(hash, &kind, 1);
      mix(hash, &step, sizeof step);
      mix_ids(hash, a, b);
      ++count;
    };
    for (const auto& event : contacts.begin) record('b', event.body_a, event.body_b);
    for (const auto& event : contacts.end) record('e', event.body_a, event.body_b);
    for (const auto& event : contacts.hit) {
      record('h', event.body_a, event.body_b);
      const float values[5] = {event.point.x, event.point.y, event.normal.x, event.normal.y,
                               event.approach_speed};
      mix(hash, values, sizeof values);
    }
    for (const auto& event : sensors.begin) record('s', event.sensor_body, event.visitor_body);
    for (const auto& event : sensors.end) record('x', event.sensor_body, event.visitor_body);
  }
  EXPECT_GT(count, 0u) << name << ": no event to pin";
  return hash;
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
  } runs[] = {{"tutorial", 900, "82be632837ab834f"},
              {"random_polygons", 900, "52b2e32ecad07187"},
              {"pyramid", 900, "e2d2e1c8d83b24be"},
              {"friction_ramp", 600, "cf8dfeba4258991d"}};
  for (const auto& each : runs) {
    EXPECT_EQ(hex(final_hash(each.scene, each.steps)), each.hash) << each.scene;
  }
}

// Joints, the new shapes and events, pinned the same way (issues 30, 31, 32; pinned from a GCC 12
// build, and Clang 14 gave the same five values): the joint solver and the rounded-shape
// collision are plain float code, so both compilers must agree here too.
TEST(CrossBuildHash, JointsShapesAndEventsArePinned) {
  const struct {
    const char* scene;
    std::int64_t steps;
    const char* hash;
  } runs[] = {{"ragdolls", 600, "aea1df92b0301ccd"},
              {"car", 480, "644d3ad681f3b3ee"},
              {"capsules", 480, "34aa2749ccebd58e"},
              {"terrain_chain", 720, "9c379ab3c9139b43"}};
  for (const auto& each : runs) {
    EXPECT_EQ(hex(final_hash(each.scene, each.steps)), each.hash) << each.scene;
  }
  EXPECT_EQ(hex(events_hash("sensors", 480)), "b1fcd0ae97909d05") << "sensors events";
}

}  // namespace
}  // namespace impulse2d::demos

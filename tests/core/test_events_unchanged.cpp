// Contact events without the walk over the contacts (world_events.cpp, `touches_unchanged`): a
// step whose prepare found no contact's touch changed and as many touching contacts as last step
// reports no begin or end and skips the walk. Each test steps a world twice, once as it runs by
// default and once made to walk every step (`WorldEvents::always_walk`), through landings,
// jumps, removals, contacts switched off and on, bodies put to sleep and woken, solver switches,
// workers and a snapshot restored: the begin and end events must be the same, step by step, and
// the default world must have skipped the walk on the steps where nothing changed.
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

// One step's begin and end events, as comparable text (kind, bodies, shapes).
std::vector<std::string> events_of(const World& world) {
  std::vector<std::string> lines;
  auto line = [](const char* kind, BodyId a, BodyId b, const ShapeId& sa, const ShapeId& sb) {
    return std::string(kind) + " " + std::to_string(a.index) + "/" + std::to_string(a.generation) + " " +
           std::to_string(b.index) + "/" + std::to_string(b.generation) + " " + std::to_string(sa.index) +
           " " + std::to_string(sb.index);
  };
  for (const auto& e : world.contact_events().begin) lines.push_back(line("begin", e.body_a, e.body_b, e.shape_a, e.shape_b));
  for (const auto& e : world.contact_events().end) lines.push_back(line("end", e.body_a, e.body_b, e.shape_a, e.shape_b));
  return lines;
}

// The bodies a scene's script acts on.
struct Scene {
  BodyId ground, lone_box, top_box;
};

// A ground, a 4-row pyramid of boxes and a box alone on the ground.
Scene build(World& world) {
  Scene scene;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.position = {0.0f, -1.0f};
  scene.ground = world.create_body(ground, make_box({20.0f, 1.0f}));
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4 - row; ++column) {
      BodyDef box;
      box.position = {-1.5f + static_cast<float>(column) + 0.5f * static_cast<float>(row), 0.5f + static_cast<float>(row)};
      scene.top_box = world.create_body(box, make_box({0.5f, 0.5f}));
    }
  }
  BodyDef lone;
  lone.position = {8.0f, 0.5f};
  scene.lone_box = world.create_body(lone, make_box({0.5f, 0.5f}));
  return scene;
}

// What happens before step `step`: a ball dropped on the pyramid, the lone box thrown up, its
// contact with the ground switched off and on (across steps and between two steps), the top
// box removed, the lone box put to sleep and woken.
void act(World& world, const Scene& scene, int step) {
  if (step == 40) {
    BodyDef ball;
    ball.position = {0.0f, 6.0f};
    world.create_body(ball, make_circle(0.4f));
  }
  if (step == 80) world.set_linear_velocity(scene.lone_box, {0.0f, 4.0f});
  if (step == 150) world.set_contact_enabled(scene.ground, scene.lone_box, false);
  if (step == 153) world.set_contact_enabled(scene.ground, scene.lone_box, true);
  if (step == 170) {
    world.set_contact_enabled(scene.ground, scene.lone_box, false);
    world.set_contact_enabled(scene.ground, scene.lone_box, true);
  }
  if (step == 190) world.remove_body(scene.top_box);
  if (step == 220) world.set_awake(scene.lone_box, false);
  if (step == 240) world.set_awake(scene.lone_box, true);
}

// Steps a world built and scripted as above (`configure` may change it before a step) with and
// without the walk on every step; returns the steps the default world skipped the walk on.
std::uint64_t compare_with_walking_twin(const WorldSettings& settings, int steps,
                                        const std::function<void(World&, const Scene&, int)>& configure = {}) {
  World skipping(settings);
  World walking(settings);
  WorldState::of(walking).events.always_walk = true;
  const Scene scene = build(skipping);
  build(walking);
  for (int step = 0; step < steps; ++step) {
    for (World* world : {&skipping, &walking}) {
      act(*world, scene, step);
      if (configure) configure(*world, scene, step);
      world->step();
    }
    EXPECT_EQ(events_of(skipping), events_of(walking)) << "step " << step;
  }
  EXPECT_EQ(WorldState::of(walking).events.walks_skipped, 0u);
  return WorldState::of(skipping).events.walks_skipped;
}

}  // namespace

TEST(EventsUnchanged, SkippedWalksGiveTheWalksEventsStepByStep) {
  const std::uint64_t skipped = compare_with_walking_twin(WorldSettings{}, 300);
  // Most steps of a resting pile change no touch: they must have been found so (the test
  // would pass vacuously if the walk were never skipped).
  EXPECT_GT(skipped, 150u);
}

TEST(EventsUnchanged, WithSleepingBodies) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  compare_with_walking_twin(settings, 400);
}

TEST(EventsUnchanged, WithWorkers) {
  WorldSettings settings;
  settings.worker_count = 2;
  EXPECT_GT(compare_with_walking_twin(settings, 300), 150u);
}

// A solver that prepares without the wide solver's visit leaves no tally: the steps after a
// switch away from the soft step (and back) walk.
TEST(EventsUnchanged, AcrossSolverSwitches) {
  compare_with_walking_twin(WorldSettings{}, 300, [](World& world, const Scene&, int step) {
    if (step == 60 || step == 200) {
      WorldSettings settings = world.settings();
      settings.solver = SolverMethod::Accumulated;
      world.set_settings(settings);
    }
    if (step == 120 || step == 260) world.set_settings(WorldSettings{});
  });
}

// Between two steps one resting contact is switched off and another, off for a while, back on:
// the pair that ends and the pair that begins leave as many touching contacts as before, so
// only each flag holding `enabled && touching` (false while a contact is off) shows the change.
TEST(EventsUnchanged, OneContactOffAndAnotherOnBetweenTwoSteps) {
  BodyId first, second;
  compare_with_walking_twin(WorldSettings{}, 200, [&](World& world, const Scene& scene, int step) {
    if (step == 0) {
      for (BodyId* id : {&first, &second}) {
        BodyDef box;
        box.position = {id == &first ? 12.0f : 15.0f, 0.5f};
        box.gravity_scale = 0.0f;  // stays where it rests while its contact is off
        *id = world.create_body(box, make_box({0.5f, 0.5f}));
      }
    }
    if (step == 60) world.set_contact_enabled(scene.ground, first, false);
    if (step == 70) {  // a step on which nothing else begins or ends
      world.set_contact_enabled(scene.ground, second, false);
      world.set_contact_enabled(scene.ground, first, true);
    }
  });
}

// A world restored from a snapshot (whose contacts do not carry their touch flags) reports
// what the world it was saved from reports.
TEST(EventsUnchanged, AfterASnapshotIsRestored) {
  World original;
  const Scene scene = build(original);
  for (int step = 0; step < 100; ++step) {
    act(original, scene, step);
    original.step();
  }
  World restored;
  restored.restore_snapshot(original.save_snapshot());
  for (int step = 100; step < 300; ++step) {
    for (World* world : {&original, &restored}) {
      act(*world, scene, step);
      world->step();
    }
    EXPECT_EQ(events_of(restored), events_of(original)) << "step " << step;
  }
  EXPECT_GT(WorldState::of(restored).events.walks_skipped, 100u);
}

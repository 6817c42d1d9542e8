/// @file test_threads.cpp
/// A multi-threaded step (`WorldSettings::worker_count`, issue 33): the state hash after every
/// step is bit-identical for 1, 2, 4 and 8 workers on a large pyramid, a ball pit, a scene with
/// joints and one of compound bodies, for every solver method; a world copied mid-run (which
/// makes its own threads) continues identically; bad worker counts are refused naming the field.

#include "core/error.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace impulse2d {
namespace {

const int worker_counts[] = {1, 2, 4, 8};

/// A static ground box whose top face is y = 0, `half_width` metres each side.
void add_ground(World& world, float half_width = 60.0f) {
  BodyDef def;
  def.type = BodyType::Static;
  def.material = materials::static_ground();
  def.position = {0.0f, -1.0f};
  world.create_body(def, make_oriented_box({half_width, 1.0f}));
}

/// Box2D v3's large pyramid at `rows` rows (rows (rows + 1) / 2 rotating unit boxes).
void build_pyramid(World& world, int rows) {
  add_ground(world);
  const float a = 0.5f;
  for (int i = 0; i < rows; ++i) {
    for (int j = i; j < rows; ++j) {
      BodyDef def;
      def.position = {(static_cast<float>(i) + 1.0f) * a + 2.0f * static_cast<float>(j - i) * a -
                          a * static_cast<float>(rows),
                      (2.0f * static_cast<float>(i) + 1.0f) * a};
      world.create_body(def, make_oriented_box({a, a}));
    }
  }
}

/// 400 balls of three sizes and a few boxes and triangles poured into a walled pit.
void build_ball_pit(World& world) {
  add_ground(world, 12.0f);
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.position = {-11.0f, 8.0f};
  world.create_body(wall, make_oriented_box({0.5f, 9.0f}));
  wall.position = {11.0f, 8.0f};
  world.create_body(wall, make_oriented_box({0.5f, 9.0f}));
  const vec2 triangle[3] = {{-0.3f, -0.2f}, {0.3f, -0.2f}, {0.0f, 0.3f}};
  for (int i = 0; i < 400; ++i) {
    BodyDef def;
    def.position = {-10.0f + 0.5f * static_cast<float>(i % 40) + 0.05f * static_cast<float>(i / 40 % 2),
                    0.5f + 0.55f * static_cast<float>(i / 40)};
    def.angle = 0.3f * static_cast<float>(i);
    def.material = materials::all()[static_cast<std::size_t>(i % 6)];
    if (i % 25 == 3) {
      world.create_body(def, make_oriented_box({0.22f, 0.18f}));
    } else if (i % 25 == 11) {
      world.create_body(def, make_polygon(triangle, 3));
    } else {
      world.create_body(def, make_circle(0.16f + 0.04f * static_cast<float>(i % 3)));
    }
  }
}

/// Two chains of 20 links hung from revolute joints, a weld-joined pair and a slider, with
/// 80 boxes dropped onto them.
void build_joints(World& world) {
  add_ground(world, 30.0f);
  BodyDef anchor_def;
  anchor_def.type = BodyType::Static;
  for (int chain = 0; chain < 2; ++chain) {
    anchor_def.position = {-8.0f + 16.0f * static_cast<float>(chain), 14.0f};
    BodyId previous = world.create_body(anchor_def, make_circle(0.1f));
    for (int k = 0; k < 20; ++k) {
      BodyDef link;
      link.position = {anchor_def.position.x + 0.5f * static_cast<float>(k) + 0.25f, 14.0f};
      const BodyId body = world.create_body(link, make_capsule({-0.25f, 0.0f}, {0.25f, 0.0f}, 0.08f));
      RevoluteJointDef joint;
      joint.body_a = previous;
      joint.body_b = body;
      joint.local_anchor_a = k == 0 ? vec2(0.0f) : vec2(0.25f, 0.0f);
      joint.local_anchor_b = {-0.25f, 0.0f};
      world.create_joint(joint);
      previous = body;
    }
  }
  BodyDef def;
  def.position = {0.0f, 2.0f};
  const BodyId left = world.create_body(def, make_oriented_box({0.5f, 0.25f}));
  def.position = {1.0f, 2.0f};
  const BodyId right = world.create_body(def, make_oriented_box({0.5f, 0.25f}));
  WeldJointDef weld;
  weld.body_a = left;
  weld.body_b = right;
  weld.local_anchor_a = {0.5f, 0.0f};
  weld.local_anchor_b = {-0.5f, 0.0f};
  world.create_joint(weld);
  for (int i = 0; i < 80; ++i) {
    BodyDef box;
    box.position = {-12.0f + 0.6f * static_cast<float>(i % 40), 18.0f + 0.7f * static_cast<float>(i / 40)};
    box.angle = 0.2f * static_cast<float>(i);
    world.create_body(box, make_oriented_box({0.2f, 0.2f}));
  }
}

/// 120 compound bodies (L shapes of three squares, and circle-and-bar dumbbells) falling into
/// a pile, among 60 single-shape boxes.
void build_compounds(World& world) {
  add_ground(world, 15.0f);
  const Shape square = make_oriented_box({0.25f, 0.25f});
  for (int i = 0; i < 180; ++i) {
    BodyDef def;
    def.position = {-12.0f + 1.2f * static_cast<float>(i % 20), 1.0f + 1.3f * static_cast<float>(i / 20)};
    def.angle = 0.37f * static_cast<float>(i);
    if (i % 3 == 2) {
      world.create_body(def, make_oriented_box({0.3f, 0.2f}));
      continue;
    }
    ShapeDef shapes[3];
    if (i % 3 == 0) {
      const vec2 places[3] = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.0f, 0.5f}};
      for (int k = 0; k < 3; ++k) {
        shapes[k].shape = square;
        shapes[k].position = places[k];
      }
    } else {
      shapes[0].shape = make_circle(0.2f);
      shapes[0].position = {-0.4f, 0.0f};
      shapes[1].shape = make_oriented_box({0.3f, 0.06f});
      shapes[2].shape = make_circle(0.2f);
      shapes[2].position = {0.4f, 0.0f};
    }
    for (ShapeDef& shape : shapes) shape.material = materials::all()[static_cast<std::size_t>(i % 6)];
    world.create_body(def, shapes, 3);
  }
}

struct Scene {
  const char* name;
  std::function<void(World&)> build;
  int steps;
};

std::vector<Scene> scenes() {
  return {{"pyramid_24", [](World& world) { build_pyramid(world, 24); }, 200},
          {"ball_pit", build_ball_pit, 240},
          {"joints", build_joints, 240},
          {"compounds", build_compounds, 240}};
}

/// The state hash after each of `steps` steps of `scene` at `settings`; with
/// `smallest_chunk`, every shared stage is split in chunks of that many elements, however small
/// (by default small stages run on one thread: these scenes would leave some stages unshared).
std::vector<std::uint64_t> hashes(const Scene& scene, const WorldSettings& settings,
                                  std::size_t smallest_chunk = 1) {
  World world(settings);
  WorldState::of(world).workers.set_smallest_chunk(smallest_chunk);
  scene.build(world);
  std::vector<std::uint64_t> result;
  for (int i = 0; i < scene.steps; ++i) {
    world.step();
    result.push_back(world.state_hash());
  }
  return result;
}

/// Expects every worker count's hashes to equal one worker's, step by step.
void expect_same_for_every_worker_count(const Scene& scene, WorldSettings settings,
                                        const std::string& label) {
  settings.worker_count = 1;
  const std::vector<std::uint64_t> single = hashes(scene, settings);
  for (int workers : worker_counts) {
    if (workers == 1) continue;
    settings.worker_count = workers;
    const std::vector<std::uint64_t> threaded = hashes(scene, settings);
    ASSERT_EQ(threaded.size(), single.size());
    for (std::size_t i = 0; i < single.size(); ++i) {
      ASSERT_EQ(threaded[i], single[i])
          << scene.name << ", " << label << ", " << workers << " workers: diverged at step " << i + 1;
    }
  }
}

TEST(Threads, SoftStepHashIsBitIdenticalForOneTwoFourAndEightWorkers) {
  for (const Scene& scene : scenes()) {
    expect_same_for_every_worker_count(scene, WorldSettings{}, "soft step");
  }
}

TEST(Threads, DefaultChunksGiveTheSameHashesAsTheSmallest) {
  // As a caller runs it: stages too small to share run on the calling thread.
  const Scene scene = scenes()[0];
  WorldSettings settings;
  const std::vector<std::uint64_t> single = hashes(scene, settings);
  settings.worker_count = 2;
  EXPECT_EQ(hashes(scene, settings, /*smallest_chunk=*/0), single);
}

TEST(Threads, FourLaneBlocksAndSleepingAreBitIdenticalForEveryWorkerCount) {
  WorldSettings settings;
  settings.solver_lanes = 4;
  settings.enable_sleeping = true;
  for (const Scene& scene : scenes()) {
    expect_same_for_every_worker_count(scene, settings, "4 lanes, sleeping");
  }
}

TEST(Threads, AccumulatedAndPerIterationAreBitIdenticalForEveryWorkerCount) {
  const std::vector<Scene> all = scenes();
  for (SolverMethod method : {SolverMethod::Accumulated, SolverMethod::PerIteration}) {
    for (const Scene& scene : {all[1], all[3]}) {
      Scene shorter = scene;
      shorter.steps = 120;
      expect_same_for_every_worker_count(shorter, settings_for(method), solver_name(method));
    }
  }
}

TEST(Threads, TheSceneReallyHasWorkForTheWorkers) {
  // A pile that has formed: hundreds of contacts, several colours (else the test proves little).
  WorldSettings settings;
  settings.worker_count = 4;
  World world(settings);
  build_pyramid(world, 24);
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_GT(world.stats().contact_count, 300);
  EXPECT_EQ(world.body_count(), 24 * 25 / 2 + 1);
}

TEST(Threads, AWorldCopiedMidRunContinuesIdentically) {
  const Scene scene = scenes()[1];
  WorldSettings settings;
  settings.worker_count = 1;
  const std::vector<std::uint64_t> single = hashes(scene, settings);

  settings.worker_count = 4;
  World original(settings);
  scene.build(original);
  for (int i = 0; i < 100; ++i) original.step();
  World copy(original);  // makes its own threads on its first step
  World assigned;
  assigned = original;
  EXPECT_EQ(copy.settings().worker_count, 4);
  WorldSettings two = assigned.settings();
  two.worker_count = 2;
  assigned.set_settings(two);  // another count on the same run: the same states
  for (int i = 100; i < scene.steps; ++i) {
    original.step();
    copy.step();
    assigned.step();
    ASSERT_EQ(original.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
    ASSERT_EQ(copy.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
    ASSERT_EQ(assigned.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
  }
}

TEST(Threads, WorkerCountChangedBetweenStepsKeepsTheSameStates) {
  const Scene scene = scenes()[0];
  const std::vector<std::uint64_t> single = hashes(scene, WorldSettings{});
  World world;
  scene.build(world);
  for (int i = 0; i < scene.steps; ++i) {
    WorldSettings settings = world.settings();
    settings.worker_count = worker_counts[(i / 7) % 4];
    world.set_settings(settings);
    world.step();
    ASSERT_EQ(world.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
  }
}

TEST(Threads, SnapshotRestoreKeepsTheRestoringWorldsWorkerCount) {
  WorldSettings settings;
  settings.worker_count = 3;
  World world(settings);
  build_ball_pit(world);
  for (int i = 0; i < 20; ++i) world.step();
  World single;  // one worker
  single.restore_snapshot(world.save_snapshot());
  EXPECT_EQ(single.settings().worker_count, 1);
  for (int i = 0; i < 20; ++i) {
    world.step();
    single.step();
    ASSERT_EQ(world.state_hash(), single.state_hash()) << "step " << i + 1;
  }
}

TEST(Threads, BadWorkerCountsAreRefusedNamingTheField) {
  for (int bad : {0, -1, 65, 1000}) {
    WorldSettings settings;
    settings.worker_count = bad;
    try {
      World world(settings);
      FAIL() << "worker_count " << bad << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("worker_count"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("1..64"), std::string::npos) << error.what();
    }
    World world;
    EXPECT_THROW(world.set_settings(settings), Error);
    EXPECT_EQ(world.settings().worker_count, 1);
  }
  for (int good : {1, 2, 64}) {
    WorldSettings settings;
    settings.worker_count = good;
    EXPECT_NO_THROW(World{settings});
  }
}

}  // namespace
}  // namespace impulse2d

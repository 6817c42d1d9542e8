// The steady-state step allocates nothing: once buffers have grown to fit a scene, stepping
// it reuses them (every solver method, every broad phase). Counted by
// tests/support/allocation_counter.cpp, compiled into this binary only.
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include "tests/support/allocation_counter.h"

using impulse2d::testing::allocation_count;

using namespace impulse2d;

namespace {

// Circles, boxes and polygons piling up, with sleeping and a bullet, so every stage runs.
void build_busy_scene(World& world) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -1};
  world.create_body(ground, make_box({20, 1}));
  const vec2 triangle[3] = {{-0.3f, -0.2f}, {0.3f, -0.2f}, {0.0f, 0.3f}};
  for (int i = 0; i < 120; ++i) {
    BodyDef def;
    def.position = {-8.0f + 0.55f * static_cast<float>(i % 30), 0.5f + 0.7f * static_cast<float>(i / 30)};
    def.angle = 0.2f * static_cast<float>(i);
    def.is_bullet = i == 7;
    switch (i % 3) {
      case 0: world.create_body(def, make_circle(0.25f)); break;
      case 1: world.create_body(def, make_oriented_box({0.25f, 0.2f})); break;
      default: world.create_body(def, make_polygon(triangle, 3)); break;
    }
  }
}

long allocations_during(World& world, int steps) {
  const long before = allocation_count();
  for (int i = 0; i < steps; ++i) world.step();
  return allocation_count() - before;
}

}  // namespace

TEST(StepAllocations, SteadyStateStepAllocatesNothing) {
  for (BroadPhaseMethod broad_phase : {BroadPhaseMethod::SortAndSweep, BroadPhaseMethod::BruteForce,
                                       BroadPhaseMethod::DynamicTree}) {
    for (SolverMethod solver :
         {SolverMethod::Accumulated, SolverMethod::PerIteration, SolverMethod::SoftStep}) {
      WorldSettings settings;
      settings.enable_sleeping = true;
      settings.broad_phase = broad_phase;
      settings.solver = solver;
      settings.substeps = solver == SolverMethod::SoftStep ? 4 : 1;
      World world(settings);
      build_busy_scene(world);
      // Warm-up: the pile forms and buffers grow to its largest contact count.
      allocations_during(world, 600);
      const long steady = allocations_during(world, 300);
      EXPECT_EQ(steady, 0) << "broad phase " << static_cast<int>(broad_phase) << ", solver "
                           << static_cast<int>(solver) << ": contacts " << world.stats().contact_count;
    }
  }
}

TEST(StepAllocations, SteadyStateStepWithWorkersAllocatesNothing) {
  // The threads are made on the first step; after that, sharing work among them allocates
  // nothing (the narrow phase's per-pair scratch grows during warm-up like the other buffers).
  for (SolverMethod solver : {SolverMethod::Accumulated, SolverMethod::SoftStep}) {
    WorldSettings settings = settings_for(solver);
    settings.enable_sleeping = true;
    settings.worker_count = 2;
    World world(settings);
    build_busy_scene(world);
    allocations_during(world, 600);
    const long steady = allocations_during(world, 300);
    EXPECT_EQ(steady, 0) << "solver " << solver_name(solver) << ": contacts "
                         << world.stats().contact_count;
  }
}

TEST(StepAllocations, SteadyStateStepBatchedByIslandAllocatesNothing) {
  // 72 separate pyramids without restitution: the soft step lays its blocks out island
  // batch by island batch and runs the batches' sub-steps one after another (or on workers).
  for (const int workers : {1, 2}) {
    WorldSettings settings;
    settings.worker_count = workers;
    World world(settings);
    WorldState::of(world).wide_contacts.set_min_island_batches(2);  // the default needs 32
    const Material crate{"Crate", 1.0f, 0.0f, 0.6f, 0.6f};  // no restitution: no bounce stage
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.material = crate;
    ground.position = {500, -1};
    world.create_body(ground, make_box({1000, 1}));
    for (int p = 0; p < 72; ++p) {
      for (int row = 0; row < 10; ++row) {
        for (int i = 0; i < 10 - row; ++i) {
          BodyDef box;
          box.material = crate;
          box.position = {14.0f * static_cast<float>(p) + static_cast<float>(i) - 0.5f * static_cast<float>(9 - row),
                          0.5f + static_cast<float>(row)};
          world.create_body(box, make_oriented_box({0.5f, 0.5f}));
        }
      }
    }
    allocations_during(world, 60);
    const long steady = allocations_during(world, 60);
    EXPECT_EQ(steady, 0) << workers << " workers: contacts " << world.stats().contact_count;
    EXPECT_TRUE(WorldState::of(world).wide_contacts.batched()) << workers << " workers";
  }
}

// A caller's task system that allocates nothing itself: it runs each task's items backwards,
// one at a time, before `enqueue` returns.
void* run_backwards(TaskFunction task, int item_count, int, void* task_context, void*) {
  for (int item = item_count - 1; item >= 0; --item) task(item, item + 1, 0, task_context);
  return nullptr;
}
void finish_nothing(void*, void*) {}

TEST(StepAllocations, SteadyStateStepThroughACallersTaskSystemAllocatesNothing) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  settings.worker_count = 2;
  settings.task_system = {&run_backwards, &finish_nothing, nullptr};
  World world(settings);
  build_busy_scene(world);
  allocations_during(world, 600);
  EXPECT_EQ(allocations_during(world, 300), 0) << "contacts " << world.stats().contact_count;
}

TEST(StepAllocations, TheCounterSeesAllocations) {
  const long before = allocation_count();
  World world;
  world.create_body(BodyDef{}, make_circle(1.0f));
  EXPECT_GT(allocation_count(), before);  // creating bodies grows the slot vectors
}

/// @file test_threads.cpp
/// A multi-threaded step (`WorldSettings::worker_count`, issue 33): the state hash after every
/// step is bit-identical for 1, 2, 4 and 8 workers on a large pyramid, a ball pit, a scene with
/// joints and one of compound bodies, for every solver method; a world copied mid-run (which
/// makes its own threads) continues identically; bad worker counts are refused naming the field.
/// The caller's threads (`WorldSettings::task_system`, issue 33 goal 2): task systems written
/// here (a small thread pool with even and with irregular ranges, one thread running the ranges
/// backwards, one running them shuffled before `enqueue` returns) give the same hashes as one
/// thread; enqueue and finish calls balance; the world starts no threads of its own; bad task
/// systems are refused, in the settings and at run time.

#include "core/error.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <dirent.h>
#include <functional>
#include <memory>
#include <mutex>
#include <numeric>
#include <random>
#include <string>
#include <thread>
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

// ---- the caller's task systems (WorldSettings::task_system) -----------------------------

/// What a task system was asked and did, to check that its calls balance.
struct TaskCounts {
  std::atomic<long> enqueues{0};      ///< `enqueue` calls
  std::atomic<long> null_handles{0};  ///< of them, those that ran everything and returned null
  std::atomic<long> finishes{0};      ///< `finish` calls
  std::atomic<long> items_enqueued{0};
  std::atomic<long> items_run{0};
  std::atomic<long> max_worker_index{-1};

  void ran(int begin, int end, int worker_index) {
    items_run += end - begin;
    long seen = max_worker_index.load();
    while (worker_index > seen && !max_worker_index.compare_exchange_weak(seen, worker_index)) {
    }
  }
};

/// Expects every enqueued task to have been finished (or run within `enqueue`), every item to
/// have run once, and some work to have been handed over at all.
void expect_balanced(const TaskCounts& counts, int worker_count, const std::string& label) {
  EXPECT_GT(counts.enqueues.load(), 0) << label;
  EXPECT_EQ(counts.enqueues.load(), counts.finishes.load() + counts.null_handles.load()) << label;
  EXPECT_EQ(counts.items_run.load(), counts.items_enqueued.load()) << label;
  EXPECT_LT(counts.max_worker_index.load(), worker_count) << label;
}

/// A caller's thread pool, as a program with its own job system would bring: `workers - 1`
/// threads and the thread calling `finish` (worker 0) take ranges from one queue. `enqueue`
/// cuts the items into even ranges (a few per worker) or irregular ones (1 to 5 times
/// `min_range`, lengths drawn from a seeded generator), queues them and returns the task;
/// `finish` runs queued ranges until the task's are all done.
class ThreadPoolTasks {
 public:
  enum class Split { Even, Irregular };

  ThreadPoolTasks(int workers, Split split) : workers_(workers), split_(split) {
    for (int i = 1; i < workers; ++i) threads_.emplace_back([this, i] { work(i); });
  }
  ~ThreadPoolTasks() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }

  /// The task system to put in `WorldSettings::task_system`.
  TaskSystem system() { return {&ThreadPoolTasks::enqueue, &ThreadPoolTasks::finish, this}; }

  TaskCounts counts;

 private:
  struct Task {
    TaskFunction function;
    void* context;
    int pending;  // ranges not yet done (guarded by mutex_)
  };
  struct Range {
    Task* task;
    int begin;
    int end;
  };

  static void* enqueue(TaskFunction function, int item_count, int min_range, void* task_context,
                       void* user_context) {
    ThreadPoolTasks& pool = *static_cast<ThreadPoolTasks*>(user_context);
    pool.counts.enqueues++;
    pool.counts.items_enqueued += item_count;
    auto* task = new Task{function, task_context, 0};
    {
      std::lock_guard<std::mutex> lock(pool.mutex_);
      const int even = std::max(min_range, (item_count + 4 * pool.workers_ - 1) / (4 * pool.workers_));
      for (int begin = 0; begin < item_count;) {
        const int length = pool.split_ == Split::Even
                               ? even
                               : min_range * static_cast<int>(1 + pool.random_() % 5);
        const int end = std::min(item_count, begin + length);
        pool.queue_.push_back({task, begin, end});
        ++task->pending;
        begin = end;
      }
    }
    pool.wake_.notify_all();
    return task;
  }

  static void finish(void* handle, void* user_context) {
    ThreadPoolTasks& pool = *static_cast<ThreadPoolTasks*>(user_context);
    pool.counts.finishes++;
    Task* task = static_cast<Task*>(handle);
    std::unique_lock<std::mutex> lock(pool.mutex_);
    while (task->pending > 0) {
      if (!pool.queue_.empty()) {
        pool.run_front(lock, 0);
      } else {
        pool.done_.wait(lock);
      }
    }
    delete task;
  }

  // Runs the first queued range as worker `worker_index` (the lock is released meanwhile).
  void run_front(std::unique_lock<std::mutex>& lock, int worker_index) {
    const Range range = queue_.front();
    queue_.pop_front();
    lock.unlock();
    range.task->function(range.begin, range.end, worker_index, range.task->context);
    counts.ran(range.begin, range.end, worker_index);
    lock.lock();
    if (--range.task->pending == 0) done_.notify_all();
  }

  void work(int worker_index) {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      run_front(lock, worker_index);
    }
  }

  const int workers_;
  const Split split_;
  std::mt19937 random_{33};
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::deque<Range> queue_;
  bool stopping_ = false;
};

/// One thread, odd orders: `Backwards` returns a handle at once and its `finish` runs the
/// items one at a time from the last to the first (as the highest worker); `Shuffled` runs
/// ranges of 1 to 3 items in a shuffled order before `enqueue` returns, and returns null.
struct OneThreadTasks {
  enum class Order { Backwards, Shuffled };
  struct Pending {
    TaskFunction function;
    int item_count;
    void* context;
  };

  OneThreadTasks(Order run_order, int workers) : order(run_order), worker_count(workers) {}

  /// The task system to put in `WorldSettings::task_system`.
  TaskSystem system() { return {&OneThreadTasks::enqueue, &OneThreadTasks::finish, this}; }

  static void* enqueue(TaskFunction function, int item_count, int, void* task_context,
                       void* user_context) {
    OneThreadTasks& tasks = *static_cast<OneThreadTasks*>(user_context);
    tasks.counts.enqueues++;
    tasks.counts.items_enqueued += item_count;
    if (tasks.order == Order::Backwards) {
      tasks.pending = {function, item_count, task_context};
      return &tasks.pending;
    }
    // The item ranges (the generator's stream, not the items' order, decides their lengths).
    tasks.ranges.clear();
    for (int begin = 0; begin < item_count;) {
      const int end = std::min(item_count, begin + 1 + static_cast<int>(tasks.random() % 3));
      tasks.ranges.push_back({begin, end});
      begin = end;
    }
    std::shuffle(tasks.ranges.begin(), tasks.ranges.end(), tasks.random);
    for (const auto& [begin, end] : tasks.ranges) {
      function(begin, end, 0, task_context);
      tasks.counts.ran(begin, end, 0);
    }
    tasks.counts.null_handles++;
    return nullptr;
  }

  static void finish(void* handle, void* user_context) {
    OneThreadTasks& tasks = *static_cast<OneThreadTasks*>(user_context);
    tasks.counts.finishes++;
    const Pending& task = *static_cast<Pending*>(handle);
    for (int item = task.item_count - 1; item >= 0; --item) {
      task.function(item, item + 1, tasks.worker_count - 1, task.context);
      tasks.counts.ran(item, item + 1, tasks.worker_count - 1);
    }
  }

  Order order;
  int worker_count;
  TaskCounts counts;
  Pending pending{};
  std::mt19937 random{7};
  std::vector<std::pair<int, int>> ranges;
};

/// Expects the hashes of `scene` with `settings` (a task system) to equal `single`, step by
/// step, every stage split into chunks of one element.
void expect_same_as_single(const Scene& scene, const WorldSettings& settings,
                           const std::vector<std::uint64_t>& single, const std::string& label) {
  const std::vector<std::uint64_t> threaded = hashes(scene, settings);
  ASSERT_EQ(threaded.size(), single.size());
  for (std::size_t i = 0; i < single.size(); ++i) {
    ASSERT_EQ(threaded[i], single[i]) << scene.name << ", " << label << ": diverged at step " << i + 1;
  }
}

TEST(TaskSystem, ACallersThreadPoolGivesTheSingleThreadedHashes) {
  for (const Scene& scene : scenes()) {
    const std::vector<std::uint64_t> single = hashes(scene, WorldSettings{});
    for (const auto& [workers, split] : {std::pair{4, ThreadPoolTasks::Split::Even},
                                         std::pair{3, ThreadPoolTasks::Split::Irregular}}) {
      ThreadPoolTasks pool(workers, split);
      WorldSettings settings;
      settings.worker_count = workers;
      settings.task_system = pool.system();
      const std::string label = std::to_string(workers) + " workers, " +
                                (split == ThreadPoolTasks::Split::Even ? "even" : "irregular") + " ranges";
      expect_same_as_single(scene, settings, single, label);
      expect_balanced(pool.counts, workers, std::string(scene.name) + ", " + label);
    }
  }
}

TEST(TaskSystem, OneThreadRunningRangesBackwardsOrShuffledGivesTheSingleThreadedHashes) {
  for (const Scene& scene : scenes()) {
    const std::vector<std::uint64_t> single = hashes(scene, WorldSettings{});
    for (const auto& [order, workers] : {std::pair{OneThreadTasks::Order::Backwards, 4},
                                         std::pair{OneThreadTasks::Order::Shuffled, 1}}) {
      OneThreadTasks tasks(order, workers);
      WorldSettings settings;
      settings.worker_count = workers;
      settings.task_system = tasks.system();
      const std::string label = order == OneThreadTasks::Order::Backwards ? "backwards" : "shuffled";
      expect_same_as_single(scene, settings, single, label);
      expect_balanced(tasks.counts, workers, std::string(scene.name) + ", " + label);
      if (order == OneThreadTasks::Order::Backwards) {
        EXPECT_EQ(tasks.counts.finishes.load(), tasks.counts.enqueues.load());
      } else {
        EXPECT_EQ(tasks.counts.null_handles.load(), tasks.counts.enqueues.load());
      }
    }
  }
}

TEST(TaskSystem, AccumulatedAndPerIterationThroughACallersPoolAreBitIdentical) {
  const std::vector<Scene> all = scenes();
  for (SolverMethod method : {SolverMethod::Accumulated, SolverMethod::PerIteration}) {
    for (const Scene& scene : {all[1], all[3]}) {
      Scene shorter = scene;
      shorter.steps = 120;
      const std::vector<std::uint64_t> single = hashes(shorter, settings_for(method));
      ThreadPoolTasks pool(2, ThreadPoolTasks::Split::Irregular);
      WorldSettings settings = settings_for(method);
      settings.worker_count = 2;
      settings.task_system = pool.system();
      expect_same_as_single(shorter, settings, single, solver_name(method));
      expect_balanced(pool.counts, 2, solver_name(method));
    }
  }
}

TEST(TaskSystem, DefaultChunksThroughACallersPoolGiveTheSameHashes) {
  // As a caller runs it: stages too small to share stay on the calling thread, the rest are
  // enqueued.
  const Scene scene = scenes()[0];
  const std::vector<std::uint64_t> single = hashes(scene, WorldSettings{});
  ThreadPoolTasks pool(2, ThreadPoolTasks::Split::Even);
  WorldSettings settings;
  settings.worker_count = 2;
  settings.task_system = pool.system();
  EXPECT_EQ(hashes(scene, settings, /*smallest_chunk=*/0), single);
  expect_balanced(pool.counts, 2, "default chunks");
}

/// Threads of this process (Linux: the entries of /proc/self/task), or -1 where unknown.
int thread_count() {
  DIR* dir = opendir("/proc/self/task");
  if (dir == nullptr) return -1;
  int count = 0;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] != '.') ++count;
  }
  closedir(dir);
  return count;
}

TEST(TaskSystem, TheWorldStartsNoThreadsOfItsOwn) {
  const int before = thread_count();
  if (before < 0) GTEST_SKIP() << "no /proc/self/task here";
  OneThreadTasks tasks(OneThreadTasks::Order::Backwards, 8);
  WorldSettings settings;
  settings.worker_count = 8;
  settings.task_system = tasks.system();
  World world(settings);
  build_ball_pit(world);
  for (int i = 0; i < 5; ++i) world.step();
  EXPECT_EQ(thread_count(), before);
  expect_balanced(tasks.counts, 8, "no threads");
  // Without the task system the same settings start seven (so the count above sees threads).
  settings.task_system = TaskSystem{};
  world.set_settings(settings);
  world.step();
  EXPECT_EQ(thread_count(), before + 7);
}

TEST(TaskSystem, SwitchingCopyingAndRestoringKeepTheSameStates) {
  const Scene scene = scenes()[1];
  const std::vector<std::uint64_t> single = hashes(scene, WorldSettings{});
  ThreadPoolTasks pool(3, ThreadPoolTasks::Split::Irregular);
  OneThreadTasks backwards(OneThreadTasks::Order::Backwards, 2);
  World world;
  scene.build(world);
  for (int i = 0; i < 100; ++i) {
    // One worker; the world's own four; the caller's pool; one caller's thread backwards.
    WorldSettings settings;
    settings.worker_count = (i / 5) % 4 == 1 ? 4 : (i / 5) % 4 == 2 ? 3 : (i / 5) % 4 == 3 ? 2 : 1;
    if ((i / 5) % 4 == 2) settings.task_system = pool.system();
    if ((i / 5) % 4 == 3) settings.task_system = backwards.system();
    world.set_settings(settings);
    world.step();
    ASSERT_EQ(world.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
  }
  WorldSettings settings;
  settings.worker_count = 3;
  settings.task_system = pool.system();
  world.set_settings(settings);
  World copy(world);  // the same task system: settings are copied
  EXPECT_EQ(copy.settings().task_system.user_context, &pool);
  World restored;      // its own (none): a snapshot does not carry the task system
  restored.restore_snapshot(world.save_snapshot());
  EXPECT_EQ(restored.settings().task_system.enqueue, nullptr);
  for (int i = 100; i < scene.steps; ++i) {
    world.step();
    copy.step();
    restored.step();
    ASSERT_EQ(world.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
    ASSERT_EQ(copy.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
    ASSERT_EQ(restored.state_hash(), single[static_cast<std::size_t>(i)]) << "step " << i + 1;
  }
  expect_balanced(pool.counts, 3, "pool");
  expect_balanced(backwards.counts, 2, "backwards");
}

void* enqueue_nothing(TaskFunction, int, int, void*, void*) { return nullptr; }
void finish_nothing(void*, void*) {}

TEST(TaskSystem, HalfATaskSystemIsRefusedNamingTheField) {
  int context = 0;
  const struct {
    TaskSystem tasks;
    const char* field;
  } bad[] = {
      {{&enqueue_nothing, nullptr, nullptr}, "task_system.finish"},
      {{nullptr, &finish_nothing, nullptr}, "task_system.enqueue"},
      {{nullptr, nullptr, &context}, "task_system.user_context"},
      {{nullptr, &finish_nothing, &context}, "task_system.enqueue"},
  };
  for (const auto& [tasks, field] : bad) {
    WorldSettings settings;
    settings.task_system = tasks;
    try {
      World world(settings);
      FAIL() << field << ": the settings were accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("WorldSettings.") + field), std::string::npos)
          << error.what();
    }
    World world;
    EXPECT_THROW(world.set_settings(settings), Error);
    EXPECT_EQ(world.settings().task_system.finish, nullptr);
    EXPECT_EQ(world.settings().task_system.enqueue, nullptr);
  }
  WorldSettings good;
  good.task_system = {&enqueue_nothing, &finish_nothing, &context};
  EXPECT_NO_THROW(World{good});
  good.worker_count = 0;  // a task system does not lift the count's range
  EXPECT_THROW(World{good}, Error);
}

/// Task systems that break the contract in one way each.
enum class Misuse { DropsTheLastItem, RunsEverythingTwice, WorkerIndexTooHigh, ReturnsNullUnrun };

void* misbehave(TaskFunction function, int item_count, int, void* task_context, void* user_context) {
  switch (*static_cast<Misuse*>(user_context)) {
    case Misuse::DropsTheLastItem:
      if (item_count > 1) function(0, item_count - 1, 0, task_context);
      break;
    case Misuse::RunsEverythingTwice:
      function(0, item_count, 0, task_context);
      function(0, item_count, 0, task_context);
      break;
    case Misuse::WorkerIndexTooHigh:
      function(0, item_count, 2, task_context);  // of 2 workers: 0 or 1
      break;
    case Misuse::ReturnsNullUnrun:
      break;
  }
  return nullptr;
}

TEST(TaskSystem, ATaskSystemThatBreaksTheContractIsCaughtNamingIt) {
  for (Misuse misuse : {Misuse::DropsTheLastItem, Misuse::RunsEverythingTwice,
                        Misuse::WorkerIndexTooHigh, Misuse::ReturnsNullUnrun}) {
    WorldSettings settings;
    settings.worker_count = 2;
    settings.task_system = {&misbehave, &finish_nothing, &misuse};
    World world(settings);
    WorldState::of(world).workers.set_smallest_chunk(1);
    build_ball_pit(world);
    try {
      world.step();
      FAIL() << "misuse " << static_cast<int>(misuse) << " went unnoticed";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("WorldSettings.task_system"), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace impulse2d

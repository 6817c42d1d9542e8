#pragma once
/// @file worker_pool.h
/// The step's workers and `parallel_for`, the one way the step uses them. A `WorkerPool` runs
/// each shared stage through a task system (`core/task_system.h`): the caller's
/// (`WorldSettings::task_system`), or by default its own `worker_count - 1` threads
/// (`WorldSettings::worker_count`). `parallel_for` splits [0, count) into contiguous chunks
/// whose bounds depend only on `count`, the chunk size and the worker count, never on timing
/// or on how the task system splits its items (the items are the chunks); the step hands it
/// only work whose elements are independent (each element's arithmetic is the same whoever
/// runs it), and does every reduction in a fixed order after it, so the state after a step is
/// bit-identical for any worker count and any task system. A world of one worker and no task
/// system has no pool: `parallel_for` on a null pool calls the function once over the whole
/// range on the calling thread.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#include "core/task_system.h"

namespace impulse2d {

/// Runs the chunks of one job at a time through a task system: the caller's (no threads of its
/// own), or its own, the default: `worker_count - 1` threads that, with the thread calling
/// `run`, share the job's items. A thread claims an item range by advancing the job's counter
/// (one atomic word with the job's number, so a thread late for a job can never claim a range
/// of the next); the own system's enqueue returns once every range is done, without waiting
/// for threads that came too late to get one. Between jobs the threads spin briefly (a step's
/// jobs follow each other within microseconds), then yield, then sleep until the next job.
/// Not copyable: a copied world makes its own (`WorkerPoolSlot`).
class WorkerPool {
 public:
  /// A job: `function(context, begin, end)` over the elements [begin, end) of one chunk.
  using ChunkFunction = void (*)(void* context, std::size_t begin, std::size_t end);

  /// Starts `worker_count - 1` threads (`worker_count` >= 2): the default task system.
  explicit WorkerPool(int worker_count);
  /// Starts no threads: runs every job through `tasks` (`enqueue` and `finish` set), a system
  /// of `worker_count` workers (>= 1).
  WorkerPool(int worker_count, const TaskSystem& tasks);
  /// Stops and joins the threads, if any.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Workers sharing a job, the calling thread included.
  int worker_count() const { return worker_count_; }
  /// True when this pool runs jobs through `tasks`: the same caller's system, or (for a null
  /// `tasks.enqueue`) threads of its own.
  bool runs_through(const TaskSystem& tasks) const {
    if (owns_threads_) return tasks.enqueue == nullptr;
    return tasks.enqueue == tasks_.enqueue && tasks.finish == tasks_.finish &&
           tasks.user_context == tasks_.user_context;
  }
  /// Chunk size `parallel_for` uses instead of its callers' minimums when nonzero (tests split
  /// even small stages, so that every shared stage runs on several threads).
  std::size_t smallest_chunk() const { return smallest_chunk_; }
  /// Sets `smallest_chunk()`.
  void set_smallest_chunk(std::size_t elements) { smallest_chunk_ = elements; }
  /// Runs `function` over [0, count) in chunks of `chunk` elements (the last may be shorter;
  /// `chunk` is raised so that there are at most 65535 chunks): enqueues one task whose items
  /// are the chunks, then finishes it; returns when every chunk is done. Throws `Error` naming
  /// `task_system` when a caller's system ran ranges outside the items, ran them with a worker
  /// index outside [0, worker_count), or returned before their lengths added up to the items.
  void run(std::size_t count, std::size_t chunk, ChunkFunction function, void* context);

 private:
  // The own system's `enqueue`: runs the task's items on the threads and the calling one and
  // returns null (done); `finish` is never called.
  static void* enqueue_on_threads(TaskFunction task, int item_count, int min_range,
                                  void* task_context, void* user_context);
  static void finish_on_threads(void* task_handle, void* user_context);
  // The job word: job number (32 bits) | range count (16) | next range to claim (16).
  static std::uint64_t job_of(std::uint64_t word) { return word >> 32; }
  // Claims and runs ranges of the job numbered `job` as worker `worker_index` until none is
  // left; returns at once when the word has moved on to another job.
  void run_ranges(std::uint64_t job, int worker_index);
  void worker_loop(int worker_index);

  int worker_count_;
  bool owns_threads_;
  TaskSystem tasks_;  // the caller's, or this pool's own (enqueue_on_threads)
  std::size_t smallest_chunk_ = 0;
  std::vector<std::thread> threads_;
  std::atomic<std::uint64_t> job_word_{0};
  std::atomic<std::size_t> done_ranges_{0};  // ranges of the current job finished
  std::atomic<int> sleepers_{0};             // threads asleep or about to be
  std::atomic<bool> stopping_{false};
  // The current job of the own threads; written by `enqueue_on_threads` before it publishes
  // the job word, read by a thread only after it claimed a range of that job (so never while
  // being written).
  int item_count_ = 0;
  int range_ = 1;
  TaskFunction task_ = nullptr;
  void* task_context_ = nullptr;
  std::mutex mutex_;
  std::condition_variable wake_;
};

/// Calls `function(begin, end)` over [0, count) split in contiguous chunks of at least
/// `min_chunk` elements, through `pool`'s task system when there is a pool and more than one
/// chunk, else once over [0, count) on this thread. `function` must treat the elements independently.
template <class Function>
void parallel_for(WorkerPool* pool, std::size_t count, std::size_t min_chunk, Function&& function) {
  if (count == 0) return;
  if (pool != nullptr && pool->smallest_chunk() != 0) min_chunk = pool->smallest_chunk();
  if (pool == nullptr || count < 2 * min_chunk) {
    function(std::size_t{0}, count);
    return;
  }
  // A few chunks per worker evens out uneven elements; the bounds follow from the counts only.
  const std::size_t workers = static_cast<std::size_t>(pool->worker_count());
  std::size_t chunk = (count + 4 * workers - 1) / (4 * workers);
  if (chunk < min_chunk) chunk = min_chunk;
  using Stored = std::remove_reference_t<Function>;
  pool->run(count, chunk,
            [](void* context, std::size_t begin, std::size_t end) {
              (*static_cast<Stored*>(context))(begin, end);
            },
            const_cast<void*>(static_cast<const void*>(&function)));
}

/// A world's pool, made on first use when `worker_count` > 1 or a task system is given, and
/// re-made when either changes. Copying gives an empty slot (the copy makes its own pool when
/// it steps).
class WorkerPoolSlot {
 public:
  WorkerPoolSlot() = default;
  /// An empty slot: threads are never shared between worlds.
  WorkerPoolSlot(const WorkerPoolSlot&) {}
  /// Keeps this slot's own pool.
  WorkerPoolSlot& operator=(const WorkerPoolSlot&) { return *this; }

  /// The pool for `worker_count` workers through `tasks` (made or re-made here): the caller's
  /// system when `tasks.enqueue` is set, else threads of its own; null for one worker and no
  /// task system.
  WorkerPool* get(int worker_count, const TaskSystem& tasks) {
    if (worker_count <= 1 && tasks.enqueue == nullptr) {
      pool_.reset();
      return nullptr;
    }
    if (!pool_ || pool_->worker_count() != worker_count || !pool_->runs_through(tasks)) {
      pool_.reset();
      pool_ = tasks.enqueue != nullptr ? std::make_unique<WorkerPool>(worker_count, tasks)
                                       : std::make_unique<WorkerPool>(worker_count);
      pool_->set_smallest_chunk(smallest_chunk_);
    }
    return pool_.get();
  }

  /// Sets the `WorkerPool::smallest_chunk` of this slot's pools, now and when re-made (tests).
  void set_smallest_chunk(std::size_t elements) {
    smallest_chunk_ = elements;
    if (pool_) pool_->set_smallest_chunk(elements);
  }

 private:
  std::unique_ptr<WorkerPool> pool_;
  std::size_t smallest_chunk_ = 0;
};

}  // namespace impulse2d

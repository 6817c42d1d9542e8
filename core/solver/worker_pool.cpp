#include "core/solver/worker_pool.h"

#include "core/error.h"

#include <string>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace impulse2d {

namespace {

// Tells the core this thread is spinning (no effect on results).
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// A waiting thread pauses this many times, then yields this many times, then sleeps: a step's
// jobs follow each other within microseconds, so its workers rarely sleep mid-step; between
// steps, and with more workers than cores, they give the cores back.
constexpr int spin_pauses = 2000;
constexpr int spin_yields = 2000;

constexpr std::uint64_t max_ranges = 0xFFFF;

std::uint64_t range_count_of(std::uint64_t word) { return (word >> 16) & 0xFFFF; }
std::uint64_t next_range_of(std::uint64_t word) { return word & 0xFFFF; }

// One `run`: its chunks are the task's items. The ranges a task system runs are counted, so
// that a caller's system that drops, repeats or misplaces them is caught after `finish`.
struct ChunkJob {
  std::size_t count;
  std::size_t chunk;
  int chunk_count;
  int worker_count;
  WorkerPool::ChunkFunction function;
  void* context;
  std::atomic<long long> items_run{0};
  std::atomic<bool> misused{false};
};

void run_job_chunks(int begin, int end, int worker_index, void* task_context) {
  ChunkJob& job = *static_cast<ChunkJob*>(task_context);
  if (begin < 0 || end > job.chunk_count || begin >= end || worker_index < 0 ||
      worker_index >= job.worker_count) {
    job.misused.store(true, std::memory_order_relaxed);
    if (begin < 0 || end > job.chunk_count || begin >= end) return;
  }
  // Each chunk's bounds follow from the counts alone, whatever range it came in.
  for (int c = begin; c < end; ++c) {
    const std::size_t first = static_cast<std::size_t>(c) * job.chunk;
    const std::size_t last = first + job.chunk < job.count ? first + job.chunk : job.count;
    job.function(job.context, first, last);
  }
  job.items_run.fetch_add(end - begin, std::memory_order_acq_rel);
}

}  // namespace

WorkerPool::WorkerPool(int worker_count)
    : worker_count_(worker_count),
      owns_threads_(true),
      tasks_{&WorkerPool::enqueue_on_threads, &WorkerPool::finish_on_threads, this} {
  threads_.reserve(static_cast<std::size_t>(worker_count - 1));
  for (int i = 1; i < worker_count; ++i) threads_.emplace_back([this, i] { worker_loop(i); });
}

WorkerPool::WorkerPool(int worker_count, const TaskSystem& tasks)
    : worker_count_(worker_count), owns_threads_(false), tasks_(tasks) {}

WorkerPool::~WorkerPool() {
  if (threads_.empty()) return;
  stopping_.store(true);
  // A job with no ranges, to wake every thread.
  job_word_.store((job_of(job_word_.load()) + 1) << 32);
  {
    std::lock_guard<std::mutex> lock(mutex_);
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void WorkerPool::run(std::size_t count, std::size_t chunk, ChunkFunction function, void* context) {
  if (count == 0) return;
  if (chunk == 0) chunk = 1;
  if ((count + chunk - 1) / chunk > max_ranges) chunk = (count + max_ranges - 1) / max_ranges;
  ChunkJob job;
  job.count = count;
  job.chunk = chunk;
  job.chunk_count = static_cast<int>((count + chunk - 1) / chunk);
  job.worker_count = worker_count_;
  job.function = function;
  job.context = context;
  // The chunks are already sized to be worth a thread: any range of them will do.
  void* const handle = tasks_.enqueue(&run_job_chunks, job.chunk_count, 1, &job, tasks_.user_context);
  if (handle != nullptr) tasks_.finish(handle, tasks_.user_context);
  const long long items_run = job.items_run.load(std::memory_order_acquire);
  if (items_run != job.chunk_count || job.misused.load(std::memory_order_relaxed)) {
    throw Error("WorldSettings.task_system: a task of " + std::to_string(job.chunk_count) +
                " items ran ranges adding up to " + std::to_string(items_run) +
                (job.misused.load() ? ", some out of [0, item_count) or with a worker index out of [0, " +
                                          std::to_string(worker_count_) + ")"
                                    : std::string()) +
                " by the time " + (handle != nullptr ? "finish returned" : "enqueue returned null") +
                ": every item must run exactly once, in ranges within [0, item_count), on workers "
                "0..worker_count - 1");
  }
}

void* WorkerPool::enqueue_on_threads(TaskFunction task, int item_count, int min_range,
                                     void* task_context, void* user_context) {
  WorkerPool& pool = *static_cast<WorkerPool*>(user_context);
  int range = min_range < 1 ? 1 : min_range;
  const std::uint64_t limit = max_ranges;
  if ((static_cast<std::uint64_t>(item_count) + range - 1) / range > limit) {
    range = static_cast<int>((static_cast<std::uint64_t>(item_count) + limit - 1) / limit);
  }
  const std::uint64_t range_count = (static_cast<std::uint64_t>(item_count) + range - 1) / range;
  pool.item_count_ = item_count;
  pool.range_ = range;
  pool.task_ = task;
  pool.task_context_ = task_context;
  pool.done_ranges_.store(0, std::memory_order_relaxed);
  const std::uint64_t job = job_of(pool.job_word_.load(std::memory_order_relaxed)) + 1;
  pool.job_word_.store(job << 32 | range_count << 16, std::memory_order_seq_cst);
  if (pool.sleepers_.load(std::memory_order_seq_cst) > 0) {
    // Taking the lock orders this job before the sleeper's check of the word.
    { std::lock_guard<std::mutex> lock(pool.mutex_); }
    pool.wake_.notify_all();
  }
  pool.run_ranges(job, 0);
  // Every range is claimed; wait for those still running on other threads.
  int waited = 0;
  while (pool.done_ranges_.load(std::memory_order_acquire) != range_count) {
    if (++waited < spin_pauses) {
      spin_pause();
    } else {
      std::this_thread::yield();
    }
  }
  return nullptr;  // done: no `finish`
}

void WorkerPool::finish_on_threads(void*, void*) {}

void WorkerPool::run_ranges(std::uint64_t job, int worker_index) {
  std::uint64_t word = job_word_.load(std::memory_order_acquire);
  for (;;) {
    if (job_of(word) != job || next_range_of(word) >= range_count_of(word)) return;
    if (!job_word_.compare_exchange_weak(word, word + 1, std::memory_order_acq_rel,
                                         std::memory_order_acquire)) {
      continue;  // `word` was reloaded
    }
    // Range claimed: the job stays this one until the range is counted done.
    const int begin = static_cast<int>(next_range_of(word)) * range_;
    const int end = begin + range_ < item_count_ ? begin + range_ : item_count_;
    task_(begin, end, worker_index, task_context_);
    done_ranges_.fetch_add(1, std::memory_order_acq_rel);
    word = job_word_.load(std::memory_order_acquire);
  }
}

void WorkerPool::worker_loop(int worker_index) {
  std::uint64_t seen = 0;
  for (;;) {
    int waited = 0;
    std::uint64_t job = job_of(job_word_.load(std::memory_order_acquire));
    while (job == seen) {
      if (waited < spin_pauses) {
        spin_pause();
      } else if (waited < spin_pauses + spin_yields) {
        std::this_thread::yield();
      } else {
        sleepers_.fetch_add(1, std::memory_order_seq_cst);
        {
          std::unique_lock<std::mutex> lock(mutex_);
          wake_.wait(lock, [&] { return job_of(job_word_.load(std::memory_order_seq_cst)) != seen; });
        }
        sleepers_.fetch_sub(1, std::memory_order_relaxed);
      }
      ++waited;
      job = job_of(job_word_.load(std::memory_order_acquire));
    }
    seen = job;
    if (stopping_.load()) return;
    run_ranges(job, worker_index);
  }
}

}  // namespace impulse2d

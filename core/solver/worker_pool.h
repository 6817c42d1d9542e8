#pragma once
/// @file worker_pool.h
/// The world's worker threads (`WorldSettings::worker_count`) and `parallel_for`, the one way
/// the step uses them. `parallel_for` splits [0, count) into contiguous chunks whose bounds
/// depend only on `count`, the chunk size and the worker count, never on timing; the step hands
/// it only work whose elements are independent (each element's arithmetic is the same whoever
/// runs it), and does every reduction in a fixed order after it, so the state after a step is
/// bit-identical for any worker count. A world of one worker has no pool: `parallel_for` on a
/// null pool calls the function once over the whole range on the calling thread.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace impulse2d {

/// `worker_count - 1` threads that, with the thread calling `run`, share the chunks of one
/// job at a time. A thread claims a chunk by advancing the job's chunk counter (one atomic word
/// with the job's number, so a thread late for a job can never claim a chunk of the next);
/// `run` returns once every chunk is done, without waiting for threads that came too late to
/// get one. Between jobs the threads spin briefly (a step's jobs follow each other within
/// microseconds), then yield, then sleep until the next job. Not copyable: a copied world makes
/// its own (`WorkerPoolSlot`).
class WorkerPool {
 public:
  /// A job: `function(context, begin, end)` over the elements [begin, end) of one chunk.
  using ChunkFunction = void (*)(void* context, std::size_t begin, std::size_t end);

  /// Starts `worker_count - 1` threads (`worker_count` >= 2).
  explicit WorkerPool(int worker_count);
  /// Stops and joins the threads.
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Workers sharing a job, the calling thread included.
  int worker_count() const { return worker_count_; }
  /// Chunk size `parallel_for` uses instead of its callers' minimums when nonzero (tests split
  /// even small stages, so that every shared stage runs on several threads).
  std::size_t smallest_chunk() const { return smallest_chunk_; }
  /// Sets `smallest_chunk()`.
  void set_smallest_chunk(std::size_t elements) { smallest_chunk_ = elements; }
  /// Runs `function` over [0, count) in chunks of `chunk` elements (the last may be shorter;
  /// `chunk` is raised so that there are at most 65535 chunks), on the threads and the calling
  /// one; returns when every chunk is done.
  void run(std::size_t count, std::size_t chunk, ChunkFunction function, void* context);

 private:
  // The job word: job number (32 bits) | chunk count (16) | next chunk to claim (16).
  static std::uint64_t job_of(std::uint64_t word) { return word >> 32; }
  // Claims and runs chunks of the job numbered `job` until none is left; returns at once when
  // the word has moved on to another job.
  void run_chunks(std::uint64_t job);
  void worker_loop();

  int worker_count_;
  std::size_t smallest_chunk_ = 0;
  std::vector<std::thread> threads_;
  std::atomic<std::uint64_t> job_word_{0};
  std::atomic<std::size_t> done_chunks_{0};  // chunks of the current job finished
  std::atomic<int> sleepers_{0};             // threads asleep or about to be
  std::atomic<bool> stopping_{false};
  // The current job; written by `run` before it publishes the job word, read by a thread
  // only after it claimed a chunk of that job (so never while being written).
  std::size_t count_ = 0;
  std::size_t chunk_ = 1;
  ChunkFunction function_ = nullptr;
  void* context_ = nullptr;
  std::mutex mutex_;
  std::condition_variable wake_;
};

/// Calls `function(begin, end)` over [0, count) split in contiguous chunks of at least
/// `min_chunk` elements, on `pool`'s workers when there is a pool and more than one chunk,
/// else once over [0, count) on this thread. `function` must treat the elements independently.
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

/// A world's pool, made on first use when `worker_count` > 1 and re-made when the count
/// changes. Copying gives an empty slot (the copy makes its own threads when it steps).
class WorkerPoolSlot {
 public:
  WorkerPoolSlot() = default;
  /// An empty slot: threads are never shared between worlds.
  WorkerPoolSlot(const WorkerPoolSlot&) {}
  /// Keeps this slot's own pool.
  WorkerPoolSlot& operator=(const WorkerPoolSlot&) { return *this; }

  /// The pool for `worker_count` workers (made or re-made here), or null for one worker.
  WorkerPool* get(int worker_count) {
    if (worker_count <= 1) {
      pool_.reset();
      return nullptr;
    }
    if (!pool_ || pool_->worker_count() != worker_count) {
      pool_.reset();
      pool_ = std::make_unique<WorkerPool>(worker_count);
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

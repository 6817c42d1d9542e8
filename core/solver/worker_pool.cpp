#include "core/solver/worker_pool.h"

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

// Pauses a waiting thread spins before it yields, and yields before it sleeps: a step's jobs
// follow each other within microseconds, so its workers rarely sleep mid-step; between steps
// (or with more workers than cores) they give the cores back.
constexpr int spin_pauses = 4000;
constexpr int spin_yields = 200;

}  // namespace

WorkerPool::WorkerPool(int worker_count) : worker_count_(worker_count) {
  threads_.reserve(static_cast<std::size_t>(worker_count - 1));
  for (int i = 1; i < worker_count; ++i) threads_.emplace_back([this] { worker_loop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_.store(true, std::memory_order_release);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void WorkerPool::run_chunks() {
  for (;;) {
    const std::size_t chunk = next_chunk_.fetch_add(1, std::memory_order_relaxed);
    if (chunk >= chunk_count_) return;
    const std::size_t begin = chunk * chunk_;
    const std::size_t end = begin + chunk_ < count_ ? begin + chunk_ : count_;
    function_(context_, begin, end);
  }
}

void WorkerPool::run(std::size_t count, std::size_t chunk, ChunkFunction function, void* context) {
  count_ = count;
  chunk_ = chunk;
  chunk_count_ = (count + chunk - 1) / chunk;
  function_ = function;
  context_ = context;
  next_chunk_.store(0, std::memory_order_relaxed);
  busy_threads_.store(static_cast<int>(threads_.size()), std::memory_order_relaxed);
  {
    // Under the lock, so a thread about to sleep sees either the new job or the notification.
    std::lock_guard<std::mutex> lock(mutex_);
    generation_.fetch_add(1, std::memory_order_release);
  }
  wake_.notify_all();
  run_chunks();
  // Every chunk is taken; wait for the threads still running theirs (and for every thread to
  // have left the job, so the next job's fields can be written).
  int waited = 0;
  while (busy_threads_.load(std::memory_order_acquire) != 0) {
    if (++waited < spin_pauses) {
      spin_pause();
    } else {
      std::this_thread::yield();
    }
  }
}

void WorkerPool::worker_loop() {
  std::uint64_t seen = 0;
  for (;;) {
    int waited = 0;
    std::uint64_t current = generation_.load(std::memory_order_acquire);
    while (current == seen) {
      if (waited < spin_pauses) {
        spin_pause();
      } else if (waited < spin_pauses + spin_yields) {
        std::this_thread::yield();
      } else {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return generation_.load(std::memory_order_acquire) != seen; });
      }
      ++waited;
      current = generation_.load(std::memory_order_acquire);
    }
    seen = current;
    if (stopping_.load(std::memory_order_acquire)) return;
    run_chunks();
    busy_threads_.fetch_sub(1, std::memory_order_acq_rel);
  }
}

}  // namespace impulse2d

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

// A waiting thread pauses this many times, then yields this many times, then sleeps: a step's
// jobs follow each other within microseconds, so its workers rarely sleep mid-step; between
// steps, and with more workers than cores, they give the cores back.
constexpr int spin_pauses = 2000;
constexpr int spin_yields = 2000;

constexpr std::uint64_t max_chunks = 0xFFFF;

std::uint64_t chunk_count_of(std::uint64_t word) { return (word >> 16) & 0xFFFF; }
std::uint64_t next_chunk_of(std::uint64_t word) { return word & 0xFFFF; }

}  // namespace

WorkerPool::WorkerPool(int worker_count) : worker_count_(worker_count) {
  threads_.reserve(static_cast<std::size_t>(worker_count - 1));
  for (int i = 1; i < worker_count; ++i) threads_.emplace_back([this] { worker_loop(); });
}

WorkerPool::~WorkerPool() {
  stopping_.store(true);
  // A job with no chunks, to wake every thread.
  job_word_.store((job_of(job_word_.load()) + 1) << 32);
  {
    std::lock_guard<std::mutex> lock(mutex_);
  }
  wake_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

void WorkerPool::run_chunks(std::uint64_t job) {
  std::uint64_t word = job_word_.load(std::memory_order_acquire);
  for (;;) {
    if (job_of(word) != job || next_chunk_of(word) >= chunk_count_of(word)) return;
    if (!job_word_.compare_exchange_weak(word, word + 1, std::memory_order_acq_rel,
                                         std::memory_order_acquire)) {
      continue;  // `word` was reloaded
    }
    // Chunk claimed: the job stays this one until the chunk is counted done.
    const std::size_t begin = static_cast<std::size_t>(next_chunk_of(word)) * chunk_;
    const std::size_t end = begin + chunk_ < count_ ? begin + chunk_ : count_;
    function_(context_, begin, end);
    done_chunks_.fetch_add(1, std::memory_order_acq_rel);
    word = job_word_.load(std::memory_order_acquire);
  }
}

void WorkerPool::run(std::size_t count, std::size_t chunk, ChunkFunction function, void* context) {
  if (chunk == 0) chunk = 1;
  if ((count + chunk - 1) / chunk > max_chunks) chunk = (count + max_chunks - 1) / max_chunks;
  const std::uint64_t chunk_count = (count + chunk - 1) / chunk;
  count_ = count;
  chunk_ = chunk;
  function_ = function;
  context_ = context;
  done_chunks_.store(0, std::memory_order_relaxed);
  const std::uint64_t job = job_of(job_word_.load(std::memory_order_relaxed)) + 1;
  job_word_.store(job << 32 | chunk_count << 16, std::memory_order_seq_cst);
  if (sleepers_.load(std::memory_order_seq_cst) > 0) {
    // Taking the lock orders this job before the sleeper's check of the word.
    { std::lock_guard<std::mutex> lock(mutex_); }
    wake_.notify_all();
  }
  run_chunks(job);
  // Every chunk is claimed; wait for those still running on other threads.
  int waited = 0;
  while (done_chunks_.load(std::memory_order_acquire) != chunk_count) {
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
    run_chunks(job);
  }
}

}  // namespace impulse2d

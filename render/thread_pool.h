#pragma once
/// @file thread_pool.h
/// A small fixed pool of threads that runs numbered tasks, the calling thread taking its
/// share; used to rasterise the CPU layers of a frame in bands of rows.

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace impulse2d::render {

/// Runs numbered tasks, 0 to the task count less one, on a fixed number of threads (the
/// caller and the workers started once), each task exactly once, in no fixed order or
/// thread; `run` returns when all are done. Tasks must not throw.
class ThreadPool {
 public:
  /// Starts `thread_count - 1` workers (none for 1 or less).
  explicit ThreadPool(int thread_count);
  /// Stops and joins the workers.
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Threads that run tasks, the caller included (at least 1).
  int thread_count() const { return static_cast<int>(workers_.size()) + 1; }
  /// Runs every task of `task_count` and waits for all of them.
  void run(int task_count, const std::function<void(int)>& task);

 private:
  void work();
  void take_tasks(const std::function<void(int)>& task, int task_count);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;      // a new batch of tasks, or stopping
  std::condition_variable finished_;  // the last busy worker is done
  const std::function<void(int)>* task_ = nullptr;
  int task_count_ = 0;
  std::atomic<int> next_task_{0};
  int busy_workers_ = 0;
  std::uint64_t batch_ = 0;  // counts the batches started, so a worker sees each once
  bool stopping_ = false;
};

/// Threads for CPU rasterisation: `LP_NUM_THREADS` when set (as llvmpipe reads it; 0 means
/// the calling thread alone), else the hardware threads.
int raster_thread_count();

}  // namespace impulse2d::render

/// @file thread_pool.cpp
#include "render/thread_pool.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace impulse2d::render {

ThreadPool::ThreadPool(int thread_count) {
  for (int i = 1; i < thread_count; ++i) workers_.emplace_back([this] { work(); });
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& worker : workers_) worker.join();
}

void ThreadPool::take_tasks(const std::function<void(int)>& task, int task_count) {
  for (int index = next_task_.fetch_add(1); index < task_count; index = next_task_.fetch_add(1)) task(index);
}

void ThreadPool::run(int task_count, const std::function<void(int)>& task) {
  if (workers_.empty() || task_count <= 1) {
    for (int index = 0; index < task_count; ++index) task(index);
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    task_ = &task;
    task_count_ = task_count;
    next_task_.store(0);
    busy_workers_ = static_cast<int>(workers_.size());
    ++batch_;
  }
  wake_.notify_all();
  take_tasks(task, task_count);
  std::unique_lock<std::mutex> lock(mutex_);
  finished_.wait(lock, [this] { return busy_workers_ == 0; });
  task_ = nullptr;
}

void ThreadPool::work() {
  std::uint64_t batch_seen = 0;
  for (;;) {
    const std::function<void(int)>* task = nullptr;
    int task_count = 0;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || batch_ != batch_seen; });
      if (stopping_) return;
      batch_seen = batch_;
      task = task_;
      task_count = task_count_;
    }
    take_tasks(*task, task_count);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (--busy_workers_ == 0) finished_.notify_one();
  }
}

int raster_thread_count() {
  if (const char* setting = std::getenv("LP_NUM_THREADS")) {
    try {
      return std::max(1, std::stoi(setting));
    } catch (const std::exception&) {
      // not a number: as if unset
    }
  }
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace impulse2d::render

/// @file frame_writer.cpp
#include "render/frame_writer.h"

#include "image/error.h"
#include "image/file_io.h"
#include "image/png.h"

#include "render/render_error.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>

namespace impulse2d::render {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Creates `directory` if needed and proves a file can be created in it.
void prepare_directory(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) {
    throw RenderError("frame writer: cannot create directory '" + directory.string() + "': " + error.message());
  }
  if (!std::filesystem::is_directory(directory, error)) {
    throw RenderError("frame writer: '" + directory.string() + "' is not a directory");
  }
  const std::filesystem::path probe = directory / (".impulse2d-write-probe-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw RenderError("frame writer: directory '" + directory.string() + "' is not writable: " +
                      std::strerror(errno));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

std::filesystem::path frame_file_path(const std::filesystem::path& directory, const std::string& scene_name,
                                      std::int64_t frame, int digits) {
  char number[32];
  std::snprintf(number, sizeof(number), "%0*lld", digits, static_cast<long long>(frame));
  return directory / (scene_name + "_" + number + ".png");
}

AsyncFrameWriter::AsyncFrameWriter(FrameWriterOptions options) : options_(std::move(options)) {
  if (options_.scene_name.empty() || options_.scene_name.find('/') != std::string::npos ||
      options_.scene_name == "." || options_.scene_name == "..") {
    throw RenderError("frame writer: scene name '" + options_.scene_name +
                      "' cannot be a file name prefix (empty, '/', '.' or '..')");
  }
  if (options_.worker_threads < 1) {
    throw RenderError("frame writer: worker_threads is " + std::to_string(options_.worker_threads) +
                      " (need >= 1)");
  }
  if (options_.queue_capacity < 1) throw RenderError("frame writer: queue_capacity must be >= 1");
  if (options_.digits < 1 || options_.digits > 18) {
    throw RenderError("frame writer: digits is " + std::to_string(options_.digits) + " (need 1..18)");
  }
  prepare_directory(options_.directory);
  for (int i = 0; i < options_.worker_threads; ++i) workers_.emplace_back([this] { work(); });
}

AsyncFrameWriter::~AsyncFrameWriter() { stop_workers(); }

std::filesystem::path AsyncFrameWriter::path_for(std::int64_t frame_number) const {
  return frame_file_path(options_.directory, options_.scene_name, frame_number, options_.digits);
}

void AsyncFrameWriter::rethrow_failure_locked() {
  if (failure_) std::rethrow_exception(failure_);
}

void AsyncFrameWriter::submit(std::int64_t frame_number, Frame frame) {
  if (frame_number < 0) throw RenderError("frame writer: frame number " + std::to_string(frame_number) + " < 0");
  if (frame.width <= 0 || frame.height <= 0) {
    throw RenderError("frame writer: frame " + std::to_string(frame_number) + " is empty (" +
                      std::to_string(frame.width) + "x" + std::to_string(frame.height) + ")");
  }
  std::unique_lock<std::mutex> lock(mutex_);
  if (finished_) throw RenderError("frame writer: submit after finish");
  queue_changed_.wait(lock, [this] { return queue_.size() < options_.queue_capacity || failure_; });
  rethrow_failure_locked();
  queue_.push_back(Job{frame_number, std::move(frame)});
  queue_changed_.notify_all();
}

Frame AsyncFrameWriter::take_spare_frame() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (spares_.empty()) return Frame{};
  Frame spare = std::move(spares_.back());
  spares_.pop_back();
  return spare;
}

void AsyncFrameWriter::finish() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (finished_) return;
  }
  stop_workers();
  std::lock_guard<std::mutex> lock(mutex_);
  rethrow_failure_locked();
}

FrameWriterStats AsyncFrameWriter::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void AsyncFrameWriter::stop_workers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    stopping_ = true;
    queue_changed_.notify_all();
  }
  for (std::thread& worker : workers_) {
    if (worker.joinable()) worker.join();
  }
}

void AsyncFrameWriter::work() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (true) {
    queue_changed_.wait(lock, [this] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;  // stopping and drained
    Job job = std::move(queue_.front());
    queue_.pop_front();
    queue_changed_.notify_all();  // room for a blocked submit
    if (failure_) continue;       // after a failure, drain without writing
    lock.unlock();
    std::exception_ptr error;
    std::size_t bytes = 0;
    double encode_seconds = 0.0;
    double write_seconds = 0.0;
    try {
      const Clock::time_point encode_start = Clock::now();
      std::vector<std::uint8_t> png = image::encode_png(job.frame, options_.encoding);
      if (options_.annotate) png = options_.annotate(job.frame_number, std::move(png));
      encode_seconds = seconds_since(encode_start);
      const Clock::time_point write_start = Clock::now();
      image::write_file_atomically(path_for(job.frame_number), png);
      write_seconds = seconds_since(write_start);
      bytes = png.size();
    } catch (const image::ImageError& failure) {
      // The writer's callers see one exception type for every way a sequence can fail.
      error = std::make_exception_ptr(RenderError(failure.what()));
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) {
      if (!failure_) failure_ = error;
      queue_changed_.notify_all();
    } else {
      stats_.frames_written += 1;
      stats_.bytes_written += bytes;
      stats_.encode_seconds += encode_seconds;
      stats_.write_seconds += write_seconds;
    }
    if (spares_.size() < options_.queue_capacity) spares_.push_back(std::move(job.frame));
  }
}

}  // namespace impulse2d::render

#pragma once
/// @file frame_writer.h
/// Writes a sequence of frames as `dir/<scene>_<frame:05>.png` on worker threads, so that
/// encoding overlaps with simulating and rendering the next frame.

#include "render/frame.h"
#include "image/png.h"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace impulse2d::render {

/// Applied to each encoded PNG before it is written (on a worker thread): frame number and
/// PNG bytes in, PNG bytes out, e.g. to add metadata. Must be safe to call from several
/// threads at once.
using PngAnnotator =
    std::function<std::vector<std::uint8_t>(std::int64_t frame_number, std::vector<std::uint8_t> png)>;

/// Where and how a frame sequence is written.
struct FrameWriterOptions {
  std::filesystem::path directory;             ///< created if missing
  std::string scene_name;                      ///< file name prefix; no '/' and not empty
  image::PngCompression encoding = image::PngCompression::Fast;    ///< PNG compression path
  int worker_threads = 1;                      ///< encoding threads, >= 1
  std::size_t queue_capacity = 4;              ///< frames waiting before `submit` blocks, >= 1
  int digits = 5;                              ///< frame numbers zero-padded to this width, 1..18
  PngAnnotator annotate;                       ///< when set, rewrites each PNG before writing
};

/// Totals of what a writer has done so far.
struct FrameWriterStats {
  std::int64_t frames_written = 0;  ///< files renamed into place
  std::uint64_t bytes_written = 0;  ///< their total size, bytes
  double encode_seconds = 0.0;      ///< wall-clock time spent encoding, summed over workers
  double write_seconds = 0.0;       ///< wall-clock time spent writing files, summed over workers
};

/// `directory/<scene>_<frame>.png` with the frame number zero-padded to `digits` (more
/// digits when the number needs them).
std::filesystem::path frame_file_path(const std::filesystem::path& directory, const std::string& scene_name,
                                      std::int64_t frame, int digits = 5);

/// A bounded queue of frames and worker threads that encode and write them. Each file's
/// bytes depend only on its frame, so the output is identical whatever the thread timing.
/// Files appear atomically (temporary file + rename); a failed write leaves no file.
class AsyncFrameWriter {
 public:
  /// Validates the options, creates the directory and checks that a file can be created in
  /// it, then starts the workers. Throws `RenderError` naming the directory or option.
  explicit AsyncFrameWriter(FrameWriterOptions options);
  /// Waits for queued frames; errors at this point are dropped (call `finish` to see them).
  ~AsyncFrameWriter();
  AsyncFrameWriter(const AsyncFrameWriter&) = delete;
  AsyncFrameWriter& operator=(const AsyncFrameWriter&) = delete;

  /// Queues `frame` as frame number `frame_number` (>= 0), blocking while the queue is full.
  /// Throws `RenderError` if an earlier frame failed, if the frame is empty, or after `finish`.
  void submit(std::int64_t frame_number, Frame frame);
  /// A frame buffer the workers are done with (or an empty one), to render the next frame
  /// into without a fresh allocation.
  Frame take_spare_frame();
  /// Waits until every queued frame is written and stops the workers. Throws `RenderError`
  /// for the first frame that failed. Later calls do nothing.
  void finish();
  /// Totals so far.
  FrameWriterStats stats() const;
  /// The file that frame `frame_number` goes to.
  std::filesystem::path path_for(std::int64_t frame_number) const;

 private:
  struct Job {
    std::int64_t frame_number;
    Frame frame;
  };
  void work();
  void rethrow_failure_locked();
  void stop_workers();

  FrameWriterOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable queue_changed_;
  std::deque<Job> queue_;
  std::vector<Frame> spares_;
  std::exception_ptr failure_;
  FrameWriterStats stats_;
  bool stopping_ = false;
  bool finished_ = false;
  std::vector<std::thread> workers_;
};

}  // namespace impulse2d::render

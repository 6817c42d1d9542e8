#pragma once
/// @file video_encoder.h
/// Optional video output through an ffmpeg process (found on PATH at run time, never
/// required to build), started without a shell (an argument vector). Frames are piped in as
/// raw RGBA; the file appears only when ffmpeg finished successfully (temporary name + rename).

#include <sys/types.h>

#include <filesystem>

#include "render/frame.h"

namespace impulse2d::demos {

/// Encodes frames into an .mp4 (H.264), .webm (VP9) or .gif file.
class VideoEncoder {
 public:
  /// Starts ffmpeg writing `output` from width x height frames at `frames_per_second`.
  /// Throws `UsageError` for an extension other than .mp4 / .webm / .gif, and `std::runtime_error`
  /// saying how to install ffmpeg when it is not on PATH, or when it cannot be started.
  VideoEncoder(std::filesystem::path output, int width, int height, double frames_per_second);
  /// Stops ffmpeg and removes the unfinished file unless `finish` succeeded.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  /// Sends one frame (must have the size given to the constructor).
  void add(const render::Frame& frame);
  /// Waits for ffmpeg and moves the file into place. Throws `std::runtime_error` when ffmpeg
  /// failed, with its exit status or signal (nothing is left behind).
  void finish();

 private:
  void abandon();

  std::filesystem::path output_;
  std::filesystem::path temporary_;
  int width_;
  int height_;
  int pipe_ = -1;    ///< ffmpeg's standard input
  pid_t child_ = -1;  ///< ffmpeg
};

/// Checks that `output` ends in .mp4, .webm or .gif (throws `UsageError` otherwise) and that ffmpeg
/// is on PATH (throws `std::runtime_error` with install instructions otherwise), before any
/// work starts.
void check_video_output(const std::filesystem::path& output);

}  // namespace impulse2d::demos

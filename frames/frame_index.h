#pragma once
/// @file frame_index.h
/// The index of a frame sequence, `<scene>_frames.csv` beside the frames: one row per frame
/// with its number, the step it shows, the simulated time and the file name, so that other
/// tools (ffmpeg, scripts, spreadsheets) can map the contiguous frame numbers back to steps.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// One frame of a sequence.
struct FrameIndexRow {
  std::int64_t frame = 0;  ///< frame number in the file name, 0, 1, 2, ...
  std::int64_t step = 0;   ///< steps simulated when it was drawn
  double time = 0.0;       ///< simulated time, seconds
  std::string file;        ///< file name, without the directory
};

/// Digits of the frame numbers in the file names of a `frame_count`-frame sequence: enough
/// for the last number, at least 5 (so that names sort in frame order).
int frame_number_digits(std::int64_t frame_count);

/// `directory/<scene>_frames.csv`.
std::filesystem::path frame_index_path(const std::filesystem::path& directory,
                                       const std::string& scene);

/// Writes `rows` as CSV with the header `frame,step,time,file` to `path` (temporary file +
/// rename). Throws `render::RenderError` naming the path when it cannot be written.
void write_frame_index(const std::filesystem::path& path, const std::vector<FrameIndexRow>& rows);

}  // namespace impulse2d::demos

/// @file frame_index.cpp
#include "frames/frame_index.h"

#include <iomanip>
#include <sstream>
#include <algorithm>

#include "image/file_io.h"

namespace impulse2d::demos {

int frame_number_digits(std::int64_t frame_count) {
  int digits = 1;
  for (std::int64_t last = frame_count - 1; last >= 10; last /= 10) ++digits;
  return std::max(5, digits);
}

std::filesystem::path frame_index_path(const std::filesystem::path& directory,
                                       const std::string& scene) {
  return directory / (scene + "_frames.csv");
}

void write_frame_index(const std::filesystem::path& path, const std::vector<FrameIndexRow>& rows) {
  std::ostringstream text;
  text << "frame,step,time,file\n" << std::setprecision(9);
  for (const FrameIndexRow& row : rows) {
    text << row.frame << "," << row.step << "," << row.time << "," << row.file << "\n";
  }
  const std::string bytes = text.str();
  image::write_file_atomically(path, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

}  // namespace impulse2d::demos

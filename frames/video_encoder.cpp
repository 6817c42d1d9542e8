/// @file video_encoder.cpp
#include "frames/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

const char* const install_hint =
    "ffmpeg was not found on PATH; --video needs it (Debian/Ubuntu: sudo apt-get install ffmpeg). "
    "The PNG frames do not need it.";

/// `text` quoted for /bin/sh.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

std::optional<std::filesystem::path> find_on_path(const char* name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  const std::string directories = path;
  std::size_t start = 0;
  while (start <= directories.size()) {
    const std::size_t colon = std::min(directories.find(':', start), directories.size());
    const std::string directory = directories.substr(start, colon - start);
    start = colon + 1;
    if (directory.empty()) continue;
    const std::filesystem::path candidate = std::filesystem::path(directory) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

void check_video_output(const std::filesystem::path& output) {
  const std::string extension = output.extension().string();
  if (extension != ".mp4" && extension != ".webm" && extension != ".gif") {
    throw UsageError("--video " + output.string() + ": the file must end in .mp4, .webm or .gif");
  }
  if (!find_on_path("ffmpeg")) throw std::runtime_error(install_hint);
}

VideoEncoder::VideoEncoder(std::filesystem::path output, int width, int height,
                           double frames_per_second)
    : output_(std::move(output)), width_(width), height_(height) {
  check_video_output(output_);
  const std::filesystem::path ffmpeg = *find_on_path("ffmpeg");
  temporary_ = output_.parent_path() / ("." + output_.stem().string() + ".partial-" +
                                        std::to_string(getpid()) + output_.extension().string());
  const std::string extension = output_.extension().string();
  const std::string even_size = "-pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'";
  const std::string filters =
      extension == ".gif"    ? "-vf 'split[a][b];[a]palettegen[p];[b][p]paletteuse'"
      : extension == ".webm" ? "-c:v libvpx-vp9 -crf 32 -b:v 0 -row-mt 1 " + even_size
                             : "-c:v libx264 " + even_size;
  const std::string command = shell_quote(ffmpeg.string()) +
                              " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s " +
                              std::to_string(width) + "x" + std::to_string(height) +
                              " -framerate " + std::to_string(frames_per_second) + " -i - " +
                              filters + " " + shell_quote(temporary_.string());
  pipe_ = popen(command.c_str(), "w");
  if (pipe_ == nullptr) throw std::runtime_error("cannot start ffmpeg (" + ffmpeg.string() + ")");
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::add(const render::Frame& frame) {
  if (frame.width != width_ || frame.height != height_) {
    throw std::runtime_error("video: frame size changed during the run");
  }
  if (std::fwrite(frame.rgba.data(), 1, frame.rgba.size(), pipe_) != frame.rgba.size()) {
    abandon();
    throw std::runtime_error("video: ffmpeg stopped reading frames (see its message above)");
  }
}

void VideoEncoder::finish() {
  const int status = pclose(pipe_);
  pipe_ = nullptr;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    abandon();
    throw std::runtime_error("video: ffmpeg failed writing " + output_.string() +
                             " (see its message above)");
  }
  std::error_code error;
  std::filesystem::rename(temporary_, output_, error);
  if (error) {
    abandon();
    throw std::runtime_error("video: cannot move the video to " + output_.string() + ": " +
                             error.message());
  }
  temporary_.clear();
}

void VideoEncoder::abandon() {
  if (pipe_ != nullptr) {
    pclose(pipe_);
    pipe_ = nullptr;
  }
  if (!temporary_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    temporary_.clear();
  }
}

}  // namespace impulse2d::demos

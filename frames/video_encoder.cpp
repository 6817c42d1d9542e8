/// @file video_encoder.cpp
#include "frames/video_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "frames/child_process.h"
#include "scene/usage_error.h"

extern char** environ;

namespace impulse2d::demos {
namespace {

const char* const install_hint =
    "ffmpeg was not found on PATH; --video needs it (Debian/Ubuntu: sudo apt-get install ffmpeg). "
    "The PNG frames do not need it.";

/// The encoder's options after the input for `extension` (.gif, .webm, else .mp4).
std::vector<std::string> encoder_arguments(const std::string& extension) {
  const std::vector<std::string> even_size = {"-pix_fmt", "yuv420p", "-vf",
                                              "pad=ceil(iw/2)*2:ceil(ih/2)*2"};
  std::vector<std::string> arguments;
  if (extension == ".gif") {
    arguments = {"-vf", "split[a][b];[a]palettegen[p];[b][p]paletteuse"};
  } else if (extension == ".webm") {
    arguments = {"-c:v", "libvpx-vp9", "-crf", "32", "-b:v", "0", "-row-mt", "1"};
    arguments.insert(arguments.end(), even_size.begin(), even_size.end());
  } else {
    arguments = {"-c:v", "libx264"};
    arguments.insert(arguments.end(), even_size.begin(), even_size.end());
  }
  return arguments;
}

}  // namespace

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
  // An argument vector, no shell. The output as a file: URL, so that no name (one starting
  // with '-', one with a colon) reads as an option or another protocol.
  std::vector<std::string> arguments = {
      ffmpeg.string(), "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo",
      "-pix_fmt", "rgba", "-s", std::to_string(width) + "x" + std::to_string(height),
      "-framerate", std::to_string(frames_per_second), "-i", "-"};
  for (const std::string& each : encoder_arguments(output_.extension().string())) {
    arguments.push_back(each);
  }
  arguments.push_back("file:" + temporary_.string());
  std::vector<char*> argv;
  for (std::string& each : arguments) argv.push_back(each.data());
  argv.push_back(nullptr);

  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0) {
    throw std::runtime_error("cannot start ffmpeg (" + ffmpeg.string() + "): no pipe: " +
                             std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[0], STDIN_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);  // the program ignores it; ffmpeg gets the usual behaviour
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  const int failed =
      posix_spawn(&child_, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(ends[0]);
  if (failed != 0) {
    ::close(ends[1]);
    child_ = -1;
    throw std::runtime_error("cannot start ffmpeg (" + ffmpeg.string() + "): " +
                             std::strerror(failed));
  }
  pipe_ = ends[1];
}

VideoEncoder::~VideoEncoder() { abandon(); }

void VideoEncoder::add(const render::Frame& frame) {
  if (frame.width != width_ || frame.height != height_) {
    throw std::runtime_error("video: frame size changed during the run");
  }
  const std::uint8_t* data = frame.rgba.data();
  std::size_t left = frame.rgba.size();
  while (left > 0) {
    const ssize_t written = ::write(pipe_, data, left);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      const std::string reason = written < 0 ? std::strerror(errno) : "no progress";
      abandon();
      throw std::runtime_error("video: ffmpeg stopped reading frames (" + reason +
                               "; see its message above)");
    }
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void VideoEncoder::finish() {
  ::close(pipe_);
  pipe_ = -1;
  const int status = wait_for_child(child_);
  child_ = -1;
  if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    abandon();
    throw std::runtime_error("video: ffmpeg failed writing " + output_.string() + ": " +
                             (status == -1 ? std::string("cannot wait for it: ") + std::strerror(errno)
                                           : describe_wait_status(status)) +
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
  if (pipe_ != -1) {
    ::close(pipe_);
    pipe_ = -1;
  }
  if (child_ > 0) {
    ::kill(child_, SIGTERM);  // no need to finish a video that is thrown away
    wait_for_child(child_);
    child_ = -1;
  }
  if (!temporary_.empty()) {
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
    temporary_.clear();
  }
}

}  // namespace impulse2d::demos

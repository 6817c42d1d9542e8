/// @file second_process.cpp
#include "golden/scenes/second_process.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <optional>
#include <thread>
#include <vector>

#include "frames/child_process.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "image/png.h"
#include "scene/interrupt.h"

extern char** environ;

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// How long an ended child has to exit after SIGTERM before it is killed.
constexpr std::chrono::seconds kGracePeriod{5};
/// How often the wait looks for a signal to this process.
constexpr std::chrono::milliseconds kPoll{5};

/// Removes a folder (and everything in it) when it goes out of scope.
class FolderRemover {
 public:
  explicit FolderRemover(fs::path folder) : folder_(std::move(folder)) {}
  ~FolderRemover() {
    std::error_code ignored;
    fs::remove_all(folder_, ignored);
  }
  FolderRemover(const FolderRemover&) = delete;
  FolderRemover& operator=(const FolderRemover&) = delete;

 private:
  fs::path folder_;
};

/// Sends SIGTERM to `child`, waits up to `kGracePeriod`, then SIGKILL, and reaps it.
void end_child(pid_t child) {
  ::kill(child, SIGTERM);
  const Clock::time_point deadline = Clock::now() + kGracePeriod;
  int status = 0;
  while (::waitpid(child, &status, WNOHANG) == 0) {
    if (Clock::now() > deadline) {
      ::kill(child, SIGKILL);
      demos::wait_for_child(child);
      return;
    }
    std::this_thread::sleep_for(kPoll);
  }
}

/// Runs `arguments` as a child process and returns its wait status. On SIGINT, SIGTERM or
/// SIGHUP to this process the child is ended and `demos::Interrupted` thrown.
int run_child(const std::vector<std::string>& arguments, const std::string& golden) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  demos::check_interrupt();
  pid_t child = 0;
  const int spawned = ::posix_spawn(&child, argv[0], nullptr, nullptr, argv.data(), environ);
  if (spawned != 0) {
    throw GoldenError("golden '" + golden + "': cannot start the second process (" +
                      arguments[0] + "): " + std::strerror(spawned));
  }
  int status = 0;
  for (;;) {
    if (demos::pending_signal() != 0) {
      end_child(child);
      demos::check_interrupt();
    }
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) return status;
    if (done == -1 && errno != EINTR) {
      throw GoldenError("golden '" + golden + "': waiting for the second process failed: " +
                        std::strerror(errno));
    }
    std::this_thread::sleep_for(kPoll);
  }
}

}  // namespace

FrameProducer other_process_producer(const std::string& executable, const GoldenSpec& spec,
                                     const fs::path& folder) {
  return [executable, spec, folder] {
    const FolderRemover remover(folder);
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) {
      throw GoldenError("golden '" + spec.id() + "': cannot create '" + folder.string() +
                        "' for the second process: " + error.message());
    }
    const fs::path png = folder / "frame.png";
    const int status = run_child(
        {executable, "golden", "frame", spec.scene_file, spec.name, "--out", png.string(),
         "--workers", std::to_string(spec.worker_count)},
        spec.id());
    std::optional<std::uint64_t> hash;
    ProducedFrame frame;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::exists(png)) {
      frame.image = image::load_png(png);
      hash = image::parse_hex_hash(image::read_text_file(png.string() + ".hash"));
    }
    if (!hash) {
      throw GoldenError("golden '" + spec.id() + "': the second process (" + executable +
                        " golden frame) failed: " + demos::describe_wait_status(status));
    }
    frame.state_hash = *hash;
    return frame;
  };
}

}  // namespace impulse2d::golden

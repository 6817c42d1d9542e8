/// @file gnuplot.cpp
#include "lab/gnuplot.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "frames/child_process.h"
#include "image/file_io.h"
#include "image/png_check.h"
#include "scene/interrupt.h"

extern char** environ;

namespace impulse2d::lab {
namespace {

/// An anonymous temporary file (removed when closed).
struct TemporaryFile {
  TemporaryFile() : file(std::tmpfile()) {
    if (file == nullptr) throw std::runtime_error(std::string("cannot create a temporary file: ") +
                                                  std::strerror(errno));
  }
  ~TemporaryFile() { std::fclose(file); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  std::FILE* file;
};

/// Both ends of a pipe, closed when it goes out of scope.
struct Pipe {
  Pipe() {
    if (::pipe2(ends, O_CLOEXEC) != 0) {
      throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    }
  }
  ~Pipe() {
    for (const int end : ends) {
      if (end >= 0) ::close(end);
    }
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  /// Closes the write end (the child holds its own copy).
  void close_write_end() {
    ::close(ends[1]);
    ends[1] = -1;
  }
  int ends[2] = {-1, -1};
};

/// Up to the first 2000 bytes of `file` from its start, without trailing blank lines.
std::string read_back(std::FILE* file) {
  std::rewind(file);
  std::string text(2000, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), file));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

/// Starts gnuplot (found on PATH, without a shell) reading its script from `script`, writing
/// its image to `image` and its complaints to `log`. Throws `std::runtime_error` with the
/// reason when it cannot be started.
pid_t spawn_gnuplot(int script, int image, int log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, script, STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, image, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, log, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);  // the program ignores it; gnuplot gets the usual behaviour
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  char program[] = "gnuplot";
  char* argv[] = {program, nullptr};
  pid_t child = 0;
  const int failed = posix_spawnp(&child, program, &actions, &attributes, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (failed != 0) throw std::runtime_error(std::string("cannot start gnuplot: ") + std::strerror(failed));
  return child;
}

/// Reads gnuplot's image from `image` until it closes it, then waits for it; returns its wait
/// status. A signal for the program (SIGINT, SIGTERM, SIGHUP) ends gnuplot with SIGTERM and
/// throws `demos::Interrupted`.
int collect_image(pid_t child, int image, std::vector<std::uint8_t>& bytes) {
  const auto stop = [child]() {
    ::kill(child, SIGTERM);
    demos::wait_for_child(child);
    demos::check_interrupt();
  };
  for (;;) {
    if (demos::pending_signal() != 0) stop();
    pollfd readable{image, POLLIN, 0};
    const int ready = ::poll(&readable, 1, 20);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    std::uint8_t buffer[65536];
    const ssize_t got = ::read(image, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    bytes.insert(bytes.end(), buffer, buffer + got);
  }
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) return status;
    if (done < 0 && errno != EINTR) {
      throw std::runtime_error(std::string("cannot wait for gnuplot: ") + std::strerror(errno));
    }
    if (demos::pending_signal() != 0) stop();
    ::usleep(2000);
  }
}

/// `script` with its `set output OUTPUT` line drawing to standard output instead.
std::string to_standard_output(const std::string& script) {
  std::string text = script;
  const std::string placeholder = "set output OUTPUT";
  for (std::size_t at = text.find(placeholder); at != std::string::npos;
       at = text.find(placeholder, at)) {
    text.replace(at, placeholder.size(), "set output");
  }
  return text;
}

}  // namespace

bool gnuplot_available() { return demos::find_on_path("gnuplot").has_value(); }

void run_gnuplot(const std::string& script, const std::string& png_path) {
  const auto fail = [&](const std::string& reason) {
    throw std::runtime_error("gnuplot failed drawing " + png_path + ": " + reason);
  };
  TemporaryFile script_file;
  TemporaryFile log_file;
  const std::string text = to_standard_output(script);
  if (std::fwrite(text.data(), 1, text.size(), script_file.file) != text.size() ||
      std::fflush(script_file.file) != 0) {
    fail(std::string("cannot write its script to a temporary file: ") + std::strerror(errno));
  }
  std::rewind(script_file.file);
  Pipe image;
  std::vector<std::uint8_t> png;
  int status = 0;
  try {
    const pid_t child = spawn_gnuplot(fileno(script_file.file), image.ends[1], fileno(log_file.file));
    image.close_write_end();
    status = collect_image(child, image.ends[0], png);
  } catch (const demos::Interrupted&) {
    throw;
  } catch (const std::runtime_error& error) {
    fail(error.what());
  }
  const std::string log = read_back(log_file.file);
  const std::string said = log.empty() ? "" : ": " + log;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail(demos::describe_wait_status(status) + said);
  if (png.empty()) fail("it drew no image (exit status 0" + said + ")");
  const std::string problem = image::png_structure_problem(png);
  if (!problem.empty()) fail("it drew a broken PNG (" + problem + ")" + said);
  try {
    image::write_file_atomically(png_path, png);
  } catch (const std::exception& error) {
    fail(error.what());
  }
}

std::string gnuplot_text(const std::string& text) {
  std::string result;
  for (const char c : text) {
    if (c == '"' || c == '\\') result += '\\';
    result += c;
  }
  return result;
}

}  // namespace impulse2d::lab

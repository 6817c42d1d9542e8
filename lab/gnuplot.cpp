/// @file gnuplot.cpp
#include "lab/gnuplot.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "frames/child_process.h"

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

/// Up to the first 2000 bytes of `file` from its start, without trailing blank lines.
std::string read_back(std::FILE* file) {
  std::rewind(file);
  std::string text(2000, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), file));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

/// Runs gnuplot (found on PATH, started without a shell) reading the script from `script`,
/// writing its image to `image` and its complaints to `log`. Returns the wait status; throws
/// `std::runtime_error` with the reason when it cannot be started.
int spawn_gnuplot(int script, int image, int log) {
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
  const int status = demos::wait_for_child(child);
  if (status == -1) {
    throw std::runtime_error(std::string("cannot wait for gnuplot: ") + std::strerror(errno));
  }
  return status;
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
  const std::filesystem::path target(png_path);
  if (target.has_parent_path()) std::filesystem::create_directories(target.parent_path());
  const std::string temporary_png = png_path + ".tmp.png";
  const auto fail = [&](const std::string& reason) {
    std::error_code ignored;
    std::filesystem::remove(temporary_png, ignored);
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
  const int image = ::open(temporary_png.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (image == -1) fail("cannot create " + temporary_png + ": " + std::strerror(errno));
  int status = 0;
  try {
    status = spawn_gnuplot(fileno(script_file.file), image, fileno(log_file.file));
  } catch (const std::runtime_error& error) {
    ::close(image);
    fail(error.what());
  }
  const bool closed = ::close(image) == 0;
  const std::string log = read_back(log_file.file);
  const std::string said = log.empty() ? "" : ": " + log;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail(demos::describe_wait_status(status) + said);
  if (!closed) fail("cannot write " + temporary_png + ": " + std::strerror(errno));
  std::error_code error;
  if (std::filesystem::file_size(temporary_png, error) == 0 || error) {
    fail("it drew no image (exit status 0" + said + ")");
  }
  std::filesystem::rename(temporary_png, target, error);
  if (error) fail("cannot move the chart into place: " + error.message());
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

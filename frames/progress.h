#pragma once
/// @file progress.h
/// Progress of a long job on stderr: a bar redrawn in place on a terminal (frames done,
/// frames/s, ETA) that fits the terminal's width, plain lines every tenth of the job
/// otherwise (logs, pipes, CI). The rate and ETA leave out the first unit (start-up).

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace impulse2d::demos {

/// Reports `done` out of `total` units of work.
class Progress {
 public:
  /// A report of `total` units labelled `label`, written to `stream`; `terminal` picks the
  /// bar (true) or plain lines (false); `unit` names the units ("frames", "runs").
  Progress(std::string label, std::int64_t total, std::FILE* stream, bool terminal,
           std::string unit = "frames");
  /// Finishes the report if `finish` was not called (a job that failed half-way).
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  /// Reports that `done` units are finished.
  void update(std::int64_t done);
  /// Ends the report (the bar gets its final newline). Later calls do nothing.
  void finish();

 private:
  std::string rate_and_eta(std::int64_t done, std::chrono::steady_clock::time_point now);

  std::string label_;
  std::string unit_;
  std::int64_t total_;
  std::FILE* stream_;
  bool terminal_;
  int columns_;
  std::int64_t last_tenth_ = -1;
  std::int64_t warm_done_ = -1;
  std::chrono::steady_clock::time_point warm_end_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
  bool finished_ = false;
};

/// True when `stream` is a terminal (isatty).
bool is_terminal(std::FILE* stream);

/// The width of the terminal: $COLUMNS when set (10..10000), else the terminal size of
/// `stream` (ioctl TIOCGWINSZ), else 80.
int terminal_columns(std::FILE* stream);

}  // namespace impulse2d::demos

/// @file progress.cpp
#include "frames/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>

namespace impulse2d::demos {
namespace {

/// "12 s", "3 min 05 s": a duration for the ETA.
std::string format_seconds(double seconds) {
  const long long whole = static_cast<long long>(std::ceil(seconds));
  if (whole < 60) return std::to_string(whole) + " s";
  char text[32];
  std::snprintf(text, sizeof(text), "%lld min %02lld s", whole / 60, whole % 60);
  return text;
}

}  // namespace

Progress::Progress(std::string label, std::int64_t total, std::FILE* stream, bool terminal,
                   std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      stream_(stream),
      terminal_(terminal),
      columns_(terminal ? terminal_columns(stream) : 0),
      last_draw_(std::chrono::steady_clock::now()) {}

std::string Progress::rate_and_eta(std::int64_t done, std::chrono::steady_clock::time_point now) {
  if (warm_done_ < 0) {
    // The first unit carries the start-up cost (renderer, shaders, first steps): the rate
    // and the ETA are measured from its end.
    warm_done_ = done;
    warm_end_ = now;
  }
  const double elapsed = std::chrono::duration<double>(now - warm_end_).count();
  if (done <= warm_done_ || elapsed <= 0.0) return "ETA ...";
  const double rate = static_cast<double>(done - warm_done_) / elapsed;
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f %s/s  ETA %s", rate, unit_.c_str(),
                format_seconds(static_cast<double>(total_ - done) / rate).c_str());
  return text;
}

void Progress::update(std::int64_t done) {
  const auto now = std::chrono::steady_clock::now();
  if (terminal_) {
    // Redraw at most 20 times a second, and always for the last unit.
    if (drawn_ && done < total_ && now - last_draw_ < std::chrono::milliseconds(50)) return;
    last_draw_ = now;
    drawn_ = true;
    const std::string rate = rate_and_eta(done, now);
    const std::string count = std::to_string(done) + "/" + std::to_string(total_) + " " + unit_;
    // "label [####....] 12/300 frames  45.0 frames/s  ETA 7 s", shortened to fit one line
    // (a full line would make the terminal wrap): the bar narrows, then the rate, then the
    // label go.
    const int room = columns_ - 1;
    std::string tail = count + "  " + rate;
    std::string head = label_ + " ";
    if (static_cast<int>(head.size() + tail.size()) + 4 > room) tail = count;
    if (static_cast<int>(head.size() + tail.size()) + 4 > room) head.clear();
    const int bar = std::min(30, room - static_cast<int>(head.size() + tail.size()) - 3);
    std::string line = head;
    if (bar >= 1) {
      const int filled = total_ > 0 ? static_cast<int>(bar * done / total_) : bar;
      line += "[" + std::string(static_cast<std::size_t>(filled), '#') +
              std::string(static_cast<std::size_t>(bar - filled), '.') + "] ";
    }
    line += tail;
    if (static_cast<int>(line.size()) > room) line.resize(static_cast<std::size_t>(std::max(room, 0)));
    // \r, the line, then clear to the end of the line (what the previous draw left).
    std::fprintf(stream_, "\r%s\033[K", line.c_str());
  } else {
    const std::int64_t tenth = total_ > 0 ? 10 * done / total_ : 10;
    if (tenth == last_tenth_) return;
    last_tenth_ = tenth;
    const std::string rate = rate_and_eta(done, now);
    std::fprintf(stream_, "%s: %lld/%lld %s, %s\n", label_.c_str(), static_cast<long long>(done),
                 static_cast<long long>(total_), unit_.c_str(), rate.c_str());
  }
  std::fflush(stream_);
}

Progress::~Progress() { finish(); }

void Progress::finish() {
  if (finished_) return;
  finished_ = true;
  if (terminal_ && drawn_) std::fputc('\n', stream_);
  std::fflush(stream_);
}

bool is_terminal(std::FILE* stream) { return isatty(fileno(stream)) != 0; }

int terminal_columns(std::FILE* stream) {
  const char* columns = std::getenv("COLUMNS");
  if (columns != nullptr) {
    char* end = nullptr;
    const long value = std::strtol(columns, &end, 10);
    if (end != columns && *end == '\0' && value >= 10 && value <= 10000) {
      return static_cast<int>(value);
    }
  }
  winsize size{};
  if (ioctl(fileno(stream), TIOCGWINSZ, &size) == 0 && size.ws_col >= 10) return size.ws_col;
  return 80;
}

}  // namespace impulse2d::demos

/// @file progress.cpp
#include "demos/progress.h"

#include <unistd.h>

#include <cmath>

namespace impulse2d::demos {

Progress::Progress(std::string label, std::int64_t total, std::FILE* stream, bool terminal,
                   std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      stream_(stream),
      terminal_(terminal),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::update(std::int64_t done) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
  const double eta = rate > 0.0 ? static_cast<double>(total_ - done) / rate : 0.0;
  if (terminal_) {
    // Redraw at most 20 times a second, and always for the last unit.
    if (drawn_ && done < total_ && now - last_draw_ < std::chrono::milliseconds(50)) return;
    last_draw_ = now;
    drawn_ = true;
    constexpr int width = 30;
    const int filled = total_ > 0 ? static_cast<int>(width * done / total_) : width;
    std::fprintf(stream_, "\r%s [%s%s] %lld/%lld %s  %.1f %s/s  ETA %.0f s   ",
                 label_.c_str(), std::string(static_cast<std::size_t>(filled), '#').c_str(),
                 std::string(static_cast<std::size_t>(width - filled), '.').c_str(),
                 static_cast<long long>(done), static_cast<long long>(total_), unit_.c_str(), rate,
                 unit_.c_str(),
                 std::ceil(eta));
  } else {
    const std::int64_t tenth = total_ > 0 ? 10 * done / total_ : 10;
    if (tenth == last_tenth_) return;
    last_tenth_ = tenth;
    std::fprintf(stream_, "%s: %lld/%lld %s, %.1f %s/s, ETA %.0f s\n", label_.c_str(),
                 static_cast<long long>(done), static_cast<long long>(total_), unit_.c_str(), rate,
                 unit_.c_str(), std::ceil(eta));
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

}  // namespace impulse2d::demos

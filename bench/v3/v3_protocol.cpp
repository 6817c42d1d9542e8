/// @file v3_protocol.cpp
#include "bench/v3/v3_protocol.h"

#include <malloc.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace impulse2d::bench_v3 {
namespace {

// The keys of the runner line, in order.
const char* const line_keys[] = {"scene", "width", "commit", "steps", "warmup", "median_ms", "min_ms",
                                 "sag", "side", "moved", "out", "non_finite", "depth", "heap_bytes"};
const char* const line_tag = "v3_runner";

std::string fixed(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.6f", value);
  return text;
}

[[noreturn]] void malformed(const std::string& runner, const std::string& why, const std::string& line) {
  throw std::runtime_error("runner " + runner + " printed a malformed line (" + why + "): '" + line + "'");
}

// A finite, non-negative decimal number (digits, one optional point), all of `text`.
bool parse_number(const std::string& text, double& value) {
  if (text.empty() || text.size() > 40) return false;
  int points = 0;
  for (const char c : text) {
    if (c == '.') {
      ++points;
    } else if (c < '0' || c > '9') {
      return false;
    }
  }
  if (points > 1 || text.front() == '.' || text.back() == '.') return false;
  value = std::strtod(text.c_str(), nullptr);
  return std::isfinite(value);
}

bool is_commit(const std::string& text) {
  return text.size() == 40 && std::all_of(text.begin(), text.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

}  // namespace

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"large_pyramid", "many_pyramids", "ball_pit"};
  return names;
}

std::string scaling_name(int bodies) { return "scaling_" + std::to_string(bodies); }

bool known_scene(const std::string& name) {
  if (std::find(scene_names().begin(), scene_names().end(), name) != scene_names().end()) return true;
  return std::any_of(compare::scaling_sizes().begin(), compare::scaling_sizes().end(),
                     [&](const compare::ScalingSize& size) { return scaling_name(size.bodies) == name; });
}

compare::CompareScene scene_by_name(const std::string& name) {
  // As bench_compare.cpp's `scenes` (full size) builds them.
  if (name == "large_pyramid") return compare::pyramid_scene("large_pyramid", 100, 500);
  if (name == "many_pyramids") return compare::many_pyramids_scene("many_pyramids", 400, 20, 10, 200);
  if (name == "ball_pit") return compare::ball_pit_scene("ball_pit", 5000, 100, 300);
  for (const compare::ScalingSize& size : compare::scaling_sizes()) {
    if (scaling_name(size.bodies) == name) return compare::scaling_scene(size.pyramids, scaling_steps);
  }
  throw std::invalid_argument("no scene named '" + name +
                              "' (large_pyramid, many_pyramids, ball_pit, scaling_990 .. scaling_100100)");
}

double thread_cpu_ms() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e3 * static_cast<double>(now.tv_sec) + 1e-6 * static_cast<double>(now.tv_nsec);
}

double heap_in_use() {
  const struct mallinfo2 info = mallinfo2();
  return static_cast<double>(info.uordblks) + static_cast<double>(info.hblkhd);
}

std::vector<double> timed_steps(const std::function<void()>& step, int warmup, int steps) {
  for (int s = 0; s < warmup; ++s) step();
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(std::max(steps, 0)));
  for (int s = 0; s < steps; ++s) {
    const double start = thread_cpu_ms();
    step();
    times.push_back(thread_cpu_ms() - start);
  }
  return times;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

Spread spread_of(const std::vector<double>& values) {
  if (values.empty()) throw std::invalid_argument("no rounds to summarise");
  for (const double value : values) {
    if (!std::isfinite(value) || value <= 0.0) {
      throw std::invalid_argument("a round's value is not a positive number: " + std::to_string(value));
    }
  }
  Spread spread;
  spread.median = median(values);
  spread.min = *std::min_element(values.begin(), values.end());
  spread.max = *std::max_element(values.begin(), values.end());
  return spread;
}

void judge(const compare::CompareScene& scene, const std::vector<lab::BodyState>& states,
           RunResult& result) {
  result.stability = compare::Stability{};
  compare::judge_final_states(scene, states, result.stability);
  result.stability.depth = compare::deepest_overlap(scene, states);
}

std::string format_runner_line(const RunResult& result) {
  const compare::Stability& figures = result.stability;
  return std::string(line_tag) + " scene=" + result.scene + " width=" + result.width +
         " commit=" + result.commit + " steps=" + std::to_string(result.steps) +
         " warmup=" + std::to_string(result.warmup) + " median_ms=" + fixed(result.median_ms) +
         " min_ms=" + fixed(result.min_ms) + " sag=" + fixed(std::max(0.0f, figures.sag)) +
         " side=" + fixed(figures.side) + " moved=" + std::to_string(figures.moved) +
         " out=" + std::to_string(figures.out) + " non_finite=" + std::to_string(figures.non_finite) +
         " depth=" + fixed(figures.depth) +
         " heap_bytes=" + std::to_string(std::llround(std::max(0.0, result.heap_bytes)));
}

RunResult parse_runner_line(const std::string& line, const std::string& runner) {
  std::string text = line;
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (text.find_first_of("\n\r\t") != std::string::npos) malformed(runner, "not one line", line);
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t space = text.find(' ', start);
    fields.push_back(text.substr(start, space == std::string::npos ? std::string::npos : space - start));
    if (space == std::string::npos) break;
    start = space + 1;
  }
  const std::size_t key_count = sizeof line_keys / sizeof line_keys[0];
  if (fields.empty() || fields[0] != line_tag) malformed(runner, "does not start with 'v3_runner '", line);
  if (fields.size() != key_count + 1) {
    malformed(runner, std::to_string(fields.size() - 1) + " fields, not " + std::to_string(key_count), line);
  }
  std::vector<std::string> values;
  for (std::size_t k = 0; k < key_count; ++k) {
    const std::string prefix = std::string(line_keys[k]) + "=";
    const std::string& field = fields[k + 1];
    if (field.compare(0, prefix.size(), prefix) != 0) {
      malformed(runner, "field " + std::to_string(k + 1) + " is not " + prefix + "...", line);
    }
    values.push_back(field.substr(prefix.size()));
  }
  RunResult result;
  result.scene = values[0];
  if (!known_scene(result.scene)) {
    malformed(runner, "unknown scene '" + result.scene + "'", line);
  }
  result.width = values[1];
  if (result.width != "sse2" && result.width != "avx2") malformed(runner, "width is not sse2 or avx2", line);
  result.commit = values[2];
  if (!is_commit(result.commit)) malformed(runner, "commit is not 40 lower-case hex digits", line);
  const auto count = [&](std::size_t k, int minimum) {
    const int value = parse_count(values[k], minimum);
    if (value < 0) malformed(runner, std::string(line_keys[k]) + " is not a whole number", line);
    return value;
  };
  const auto number = [&](std::size_t k) {
    double value = 0.0;
    if (!parse_number(values[k], value)) {
      malformed(runner, std::string(line_keys[k]) + " is not a non-negative number", line);
    }
    return value;
  };
  result.steps = count(3, 1);
  result.warmup = count(4, 0);
  result.median_ms = number(5);
  result.min_ms = number(6);
  result.stability.sag = static_cast<float>(number(7));
  result.stability.side = static_cast<float>(number(8));
  result.stability.moved = count(9, 0);
  result.stability.out = count(10, 0);
  result.stability.non_finite = count(11, 0);
  result.stability.depth = static_cast<float>(number(12));
  result.heap_bytes = number(13);
  if (values[13].find('.') != std::string::npos) malformed(runner, "heap_bytes is not whole", line);
  if (result.min_ms > result.median_ms) malformed(runner, "min_ms above median_ms", line);
  return result;
}

int parse_count(const std::string& text, int minimum) {
  if (text.empty() || text.size() > 9) return -1;
  for (const char c : text) {
    if (c < '0' || c > '9') return -1;
  }
  const long value = std::stol(text);
  if (value < minimum || value > 100000000) return -1;
  return static_cast<int>(value);
}

}  // namespace impulse2d::bench_v3

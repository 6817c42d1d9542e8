/// @file frame_selection.cpp
#include "scene/frame_selection.h"

#include "scene/usage_error.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

namespace impulse2d::demos {

namespace {

[[noreturn]] void reject(const std::string& spec, const std::string& reason) {
  throw UsageError("frame selection '" + spec + "': " + reason);
}

// A non-negative decimal integer, or nothing for an empty field.
std::optional<std::int64_t> parse_number(const std::string& spec, const std::string& field, const char* what) {
  if (field.empty()) return std::nullopt;
  if (!std::all_of(field.begin(), field.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    reject(spec, std::string(what) + " '" + field + "' is not a non-negative whole number");
  }
  errno = 0;
  const long long value = std::strtoll(field.c_str(), nullptr, 10);
  if (errno == ERANGE) reject(spec, std::string(what) + " '" + field + "' is too large");
  return static_cast<std::int64_t>(value);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

}  // namespace

FrameSelection::FrameSelection() : ranges_{Range{}} {}

FrameSelection FrameSelection::every(std::int64_t k) {
  if (k < 1) throw UsageError("frame selection: every " + std::to_string(k) + " steps (need k >= 1)");
  return FrameSelection({Range{0, std::nullopt, k}});
}

FrameSelection FrameSelection::parse(const std::string& spec) {
  if (spec.empty()) reject(spec, "empty (use e.g. '::1' for every step)");
  std::vector<Range> ranges;
  for (const std::string& item : split(spec, ',')) {
    const std::vector<std::string> fields = split(item, ':');
    if (item.empty() || fields.size() > 3) {
      reject(spec, "range '" + item + "' is not of the form A, A:B or A:B:k");
    }
    Range range;
    range.first = parse_number(spec, fields[0], "start").value_or(0);
    if (fields.size() == 1) {
      range.last = range.first;
    } else {
      range.last = parse_number(spec, fields[1], "end");
      if (fields.size() == 3) {
        range.stride = parse_number(spec, fields[2], "step").value_or(1);
        if (range.stride < 1) reject(spec, "step must be at least 1");
      }
    }
    if (range.last && *range.last < range.first) {
      reject(spec, "range '" + item + "' ends before it starts");
    }
    ranges.push_back(range);
  }
  return FrameSelection(std::move(ranges));
}

bool FrameSelection::contains(std::int64_t step) const {
  for (const Range& range : ranges_) {
    if (step < range.first || (range.last && step > *range.last)) continue;
    if ((step - range.first) % range.stride == 0) return true;
  }
  return false;
}

std::optional<std::int64_t> FrameSelection::last() const {
  std::int64_t result = -1;
  for (const Range& range : ranges_) {
    if (!range.last) return std::nullopt;
    const std::int64_t last_hit = range.first + (*range.last - range.first) / range.stride * range.stride;
    result = std::max(result, last_hit);
  }
  return result;
}

std::vector<std::int64_t> FrameSelection::steps_up_to(std::int64_t last_step,
                                                     std::size_t max_count) const {
  std::vector<std::int64_t> steps;
  for (const Range& range : ranges_) {
    const std::int64_t end = range.last ? std::min(*range.last, last_step) : last_step;
    for (std::int64_t step = range.first; step <= end && steps.size() <= max_count;
         step = step > end - range.stride ? end + 1 : step + range.stride) {
      steps.push_back(step);
    }
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  }
  if (steps.size() > max_count + 1) steps.resize(max_count + 1);
  return steps;
}

}  // namespace impulse2d::demos

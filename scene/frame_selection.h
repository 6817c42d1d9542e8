#pragma once
/// @file frame_selection.h
/// Which steps of a run become frames: every k-th step, or ranges "A:B:k".

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// A set of step numbers (>= 0) to turn into frames.
class FrameSelection {
 public:
  /// Every step.
  FrameSelection();
  /// Steps 0, k, 2k, ... Throws `UsageError` unless k >= 1.
  static FrameSelection every(std::int64_t k);
  /// Parses a comma-separated list of ranges. Each range is `A:B:k` (A, A+k, ... up to and
  /// including B), `A:B` (k = 1) or `A` (that step alone); A defaults to 0 and B to no end,
  /// so `::10` is every 10th step and `100:` is every step from 100. Throws `UsageError`
  /// naming the spec and the reason for anything else (negative numbers, k < 1, B < A).
  static FrameSelection parse(const std::string& spec);

  /// True when step `step` is selected.
  bool contains(std::int64_t step) const;
  /// The last selected step, or nothing when some range has no end.
  std::optional<std::int64_t> last() const;
  /// The selected steps in 0..`last_step`, ascending, without repeats; at most `max_count`
  /// of them (more would be a request too large to honour: the caller gets `max_count` + 1
  /// steps and reports it). Cost proportional to the steps returned, not to `last_step`.
  std::vector<std::int64_t> steps_up_to(std::int64_t last_step, std::size_t max_count) const;

 private:
  struct Range {
    std::int64_t first = 0;
    std::optional<std::int64_t> last;  // inclusive; none = no end
    std::int64_t stride = 1;
  };
  explicit FrameSelection(std::vector<Range> ranges) : ranges_(std::move(ranges)) {}
  std::vector<Range> ranges_;
};

}  // namespace impulse2d::demos

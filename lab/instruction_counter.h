#pragma once
/// @file instruction_counter.h
/// User-space instructions retired by this thread (Linux perf_event_open), a cost measure that
/// does not move with the machine's load. Unavailable (and harmless) where the kernel or a
/// container forbids performance counters.

#include <cstdint>

namespace impulse2d::lab {

/// One hardware instruction counter for the calling thread.
class InstructionCounter {
 public:
  /// Opens the counter; `available()` says whether that worked.
  InstructionCounter();
  ~InstructionCounter();
  InstructionCounter(const InstructionCounter&) = delete;
  InstructionCounter& operator=(const InstructionCounter&) = delete;
  /// True when the counter could be opened.
  bool available() const { return descriptor_ >= 0; }
  /// Resets and starts counting.
  void start();
  /// Stops counting and returns the instructions since `start()` (0 when unavailable).
  std::uint64_t stop();

 private:
  int descriptor_ = -1;
};

}  // namespace impulse2d::lab

#pragma once
/// @file character_input.h
/// What a player does in one fixed step, and a script of those states over a run, so that a
/// character's run is deterministic (demos, golden images and tests replay the same script).

#include <cstdint>
#include <vector>

namespace impulse2d {

/// The controls of a character during one fixed step.
struct CharacterInput {
  float move_x = 0.0f;  ///< horizontal axis, -1 (full left) .. +1 (full right)
  bool jump = false;    ///< jump button held; a press is a step where it is held and was not
  bool down = false;    ///< down held; with a jump press on a one-way platform it drops through

  /// Inputs are equal when every control is.
  bool operator==(const CharacterInput& other) const {
    return move_x == other.move_x && jump == other.jump && down == other.down;
  }
};

/// From `step` on, the controls are `input` (until the next event).
struct InputEvent {
  std::int64_t step = 0;  ///< world step index (0 = the first step taken)
  CharacterInput input;   ///< controls from that step on
};

/// A piecewise-constant input over steps: a sorted list of events. Before the first event the
/// input is neutral (no move, nothing held).
class InputScript {
 public:
  /// From step `step` on, the input is `input`; an event at the same step is replaced.
  /// Throws `Error` when `step` < 0 or `move_x` is not finite or outside [-1, 1].
  void set(std::int64_t step, const CharacterInput& input);
  /// The input during step `step`.
  CharacterInput at(std::int64_t step) const;
  /// The events in ascending step order.
  const std::vector<InputEvent>& events() const { return events_; }
  /// Step of the last event (-1 for an empty script).
  std::int64_t last_event_step() const { return events_.empty() ? -1 : events_.back().step; }

 private:
  std::vector<InputEvent> events_;  // ascending, unique steps
};

}  // namespace impulse2d

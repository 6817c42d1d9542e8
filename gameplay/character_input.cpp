#include "gameplay/character_input.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse2d {

void InputScript::set(std::int64_t step, const CharacterInput& input) {
  if (step < 0) throw Error("InputScript::set: step must be >= 0 (got " + std::to_string(step) + ")");
  if (!(std::isfinite(input.move_x) && input.move_x >= -1.0f && input.move_x <= 1.0f)) {
    throw Error("InputScript::set: move_x must be finite and in [-1, 1] (got " +
                std::to_string(input.move_x) + ")");
  }
  const auto at_or_after = std::lower_bound(
      events_.begin(), events_.end(), step,
      [](const InputEvent& event, std::int64_t wanted) { return event.step < wanted; });
  if (at_or_after != events_.end() && at_or_after->step == step) {
    at_or_after->input = input;
  } else {
    events_.insert(at_or_after, InputEvent{step, input});
  }
}

CharacterInput InputScript::at(std::int64_t step) const {
  const auto after = std::upper_bound(
      events_.begin(), events_.end(), step,
      [](std::int64_t wanted, const InputEvent& event) { return wanted < event.step; });
  if (after == events_.begin()) return CharacterInput{};
  return std::prev(after)->input;
}

}  // namespace impulse2d

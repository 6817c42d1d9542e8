#pragma once
/// @file stressors.h
/// The stressors of the stability map: each is a family of lab scenarios indexed by one value
/// (stack height, mass ratio, bullet speed, time step, initial overlap, elastic pile size,
/// friction ramp angle, a hanging chain's load and its time step), swept until a method breaks.

#include <functional>
#include <string>
#include <vector>

#include "lab/lab_scenario.h"

namespace impulse2d::lab {

/// One stressor.
struct Stressor {
  std::string name;          ///< e.g. "stack_height"
  std::string question;      ///< what passing means, e.g. "a stack of n boxes stands 30 s"
  std::string unit;          ///< of the value, e.g. "boxes", "m/s"
  std::vector<double> ladder;  ///< values in order of difficulty (easiest first)
  bool integer = false;      ///< values are whole numbers (bisection stops at neighbours)
  bool sets_time_step = false;  ///< the value is the method's time step, in milliseconds
  /// The scenarios of one value (a run passes the value iff it passes all of them).
  std::function<std::vector<LabScenario>(double value)> scenarios;
};

/// Every stressor. `quick` gives shorter runs and shorter ladders.
std::vector<Stressor> stressors(bool quick);

}  // namespace impulse2d::lab

/// @file work_budget.cpp
#include "lab/work_budget.h"

#include <cmath>

#include "scene/usage_error.h"

namespace impulse2d::lab {

std::string grouped(std::int64_t value) {
  std::string digits = std::to_string(value < 0 ? -value : value);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(at, ",");
  return value < 0 ? "-" + digits : digits;
}

std::string describe_work(const WorkEstimate& estimate) {
  const double minutes = estimate.seconds / 60.0;
  const std::string time = estimate.seconds < 90.0
                               ? std::to_string(std::max<long>(1, std::lround(estimate.seconds))) + " s"
                           : minutes < 180.0 ? std::to_string(std::lround(minutes)) + " min"
                                             : grouped(std::lround(minutes / 60.0)) + " h";
  return grouped(estimate.runs) + " runs, " + grouped(estimate.steps) + " steps (about " + time +
         " on this machine)";
}

void check_budget(const std::string& command, const WorkEstimate& estimate, std::int64_t amount,
                  std::int64_t bound, const std::string& unit, bool force,
                  const std::string& smaller) {
  if (amount <= bound || force) return;
  throw demos::UsageError(command + ": " + describe_work(estimate) + " exceeds the bound of " +
                          grouped(bound) + " " + unit +
                          " without --force (" + smaller + " make it smaller)");
}

}  // namespace impulse2d::lab

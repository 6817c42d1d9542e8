/// @file compare_json.cpp
#include "golden/compare_json.h"

#include "image/hex_hash.h"

namespace impulse2d::golden {

namespace {

using nlohmann::json;

std::string outcome_id(CompareOutcome outcome) {
  switch (outcome) {
    case CompareOutcome::ExactMatch:
      return "exact_match";
    case CompareOutcome::WithinTolerance:
      return "within_tolerance";
    case CompareOutcome::ExceedsTolerance:
      return "exceeds_tolerance";
    case CompareOutcome::SizeMismatch:
      return "size_mismatch";
  }
  return "unknown";
}

std::string rule_id(ToleranceRule rule) {
  switch (rule) {
    case ToleranceRule::DifferingPixels:
      return "max_differing_pixels";
    case ToleranceRule::DifferingRatio:
      return "max_differing_ratio";
    case ToleranceRule::WindowDensity:
      return "max_window_pixels";
  }
  return "unknown";
}

}  // namespace

json comparison_to_json(const CompareResult& result) {
  const DiffMetrics& metrics = result.metrics;
  json violations = json::array();
  for (const RuleViolation& violation : result.violations) {
    violations.push_back({{"rule", rule_id(violation.rule)},
                          {"measured", violation.measured},
                          {"limit", violation.limit},
                          {"text", violation.text}});
  }
  json tolerance = tolerance_to_json(result.tolerance);
  tolerance["origin"] = result.tolerance.describe_origin();
  const PixelBox& box = metrics.differing_box;
  return {{"outcome", outcome_id(result.outcome)},
          {"expected_size", {result.expected_width, result.expected_height}},
          {"actual_size", {result.actual_width, result.actual_height}},
          {"expected_rgba_hash", image::to_hex_hash(result.expected_hash)},
          {"actual_rgba_hash", image::to_hex_hash(result.actual_hash)},
          {"metrics",
           {{"changed_pixels", metrics.changed_pixels},
            {"masked_pixels", metrics.masked_pixels},
            {"differing_pixels", metrics.differing_pixels},
            {"differing_ratio", metrics.differing_ratio},
            {"max_channel_delta", metrics.max_channel_delta},
            {"channel_max_delta", metrics.channel_max_delta},
            {"alpha_only", metrics.alpha_only},
            {"window_size", {metrics.window_width, metrics.window_height}},
            {"worst_window_pixels", metrics.worst_window_pixels},
            {"worst_window_at", {metrics.worst_window_x, metrics.worst_window_y}},
            {"differing_box",
             box.empty() ? json(nullptr) : json{box.min_x, box.min_y, box.max_x, box.max_y}}}},
          {"violations", violations},
          {"tolerance", tolerance}};
}

}  // namespace impulse2d::golden

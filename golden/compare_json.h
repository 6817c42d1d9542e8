#pragma once
/// @file compare_json.h
/// A comparison as JSON, the form metrics.json files and the HTML report read.

#include <nlohmann/json.hpp>

#include "golden/compare.h"

namespace impulse2d::golden {

/// Outcome, both sizes and RGBA hashes, the metrics, each failed rule with its measured value
/// and limit, and the tolerance with where it came from.
nlohmann::json comparison_to_json(const CompareResult& result);

}  // namespace impulse2d::golden

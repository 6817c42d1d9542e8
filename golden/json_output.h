#pragma once
/// @file json_output.h
/// JSON the golden code writes (sidecars, metrics.json, run.json): numbers in their shortest
/// form that reads back to the same value, single-precision values as the float they are
/// (0.02f as 0.02, not 0.019999999552965164), and never a non-finite number (JSON has none:
/// nlohmann would write `null`).

#include <nlohmann/json.hpp>

#include <string>

namespace impulse2d::golden {

/// The double whose shortest decimal form is `value`'s shortest form as a float
/// (`std::to_chars(float)`), so the JSON shows 0.02 for 0.02f. Reading it back as a double
/// and converting to float gives `value` exactly.
double float_for_json(float value);

/// `value.dump(2)` and a newline. Throws `GoldenError` "<file>: <json path>: <number> is not
/// finite; not written" for the first NaN or infinity, before anything is written.
std::string dump_json_for_file(const nlohmann::json& value, const std::string& file);

}  // namespace impulse2d::golden

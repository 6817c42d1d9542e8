/// @file json_output.cpp
#include "golden/json_output.h"

#include <charconv>
#include <cmath>

#include "golden/error.h"

namespace impulse2d::golden {

using nlohmann::json;

namespace {

/// Throws for the first non-finite number in `value`; `path` is where it is ("" at the top).
void require_finite(const json& value, const std::string& path, const std::string& file) {
  if (value.is_number_float() && !std::isfinite(value.get<double>())) {
    throw GoldenError(file + ": " + (path.empty() ? "the value" : path) + ": " +
                      std::to_string(value.get<double>()) + " is not finite; not written");
  }
  if (value.is_object()) {
    for (const auto& item : value.items()) {
      require_finite(item.value(), path.empty() ? item.key() : path + "." + item.key(), file);
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) {
      require_finite(value[i], path + "[" + std::to_string(i) + "]", file);
    }
  }
}

}  // namespace

double float_for_json(float value) {
  if (!std::isfinite(value)) return value;
  char text[32];
  const std::to_chars_result written = std::to_chars(text, text + sizeof text, value);
  double shortest = value;
  std::from_chars(text, written.ptr, shortest);
  return shortest;
}

std::string dump_json_for_file(const json& value, const std::string& file) {
  require_finite(value, "", file);
  return value.dump(2) + "\n";
}

}  // namespace impulse2d::golden

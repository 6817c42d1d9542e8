/// @file option_numbers.cpp
#include "lab/option_numbers.h"

#include <sstream>

#include "scene/strict_number.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {
namespace {

/// `value` as a person writes it (no trailing zeros).
std::string plain(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

std::int64_t count_option(const std::string& flag, const std::string& text, std::int64_t minimum,
                          std::int64_t maximum) {
  const std::optional<std::int64_t> value = demos::parse_whole_number(text, maximum);
  if (!value || *value < minimum) {
    throw demos::UsageError(flag + " '" + text + "': expected a whole number in " +
                            std::to_string(minimum) + ".." + std::to_string(maximum) + " (" +
                            demos::whole_number_syntax + ")");
  }
  return *value;
}

double decimal_option(const std::string& flag, const std::string& text, double minimum,
                      double maximum, const std::string& unit) {
  const std::optional<double> value = demos::parse_decimal(text, false);
  if (!value || !(*value > minimum && *value <= maximum)) {
    throw demos::UsageError(flag + " '" + text + "': expected a number in (" + plain(minimum) +
                            ", " + plain(maximum) + "] " + unit + " (" + demos::decimal_syntax +
                            ")");
  }
  return *value;
}

std::pair<int, int> parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const std::optional<std::int64_t> index =
      slash == std::string::npos ? std::nullopt : demos::parse_whole_number(text.substr(0, slash), 10000);
  const std::optional<std::int64_t> count =
      slash == std::string::npos ? std::nullopt : demos::parse_whole_number(text.substr(slash + 1), 10000);
  if (!index || !count || *count < 1 || *index < 1 || *index > *count) {
    throw demos::UsageError("--shard '" + text +
                            "': expected K/N with 1 <= K <= N <= 10000 in digits only, e.g. 2/4");
  }
  return {static_cast<int>(*index), static_cast<int>(*count)};
}

}  // namespace impulse2d::lab

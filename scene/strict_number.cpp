/// @file strict_number.cpp
#include "scene/strict_number.h"

#include <cmath>
#include <cstdlib>

namespace impulse2d::demos {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The index after the digits starting at `at` in `text`.
std::size_t skip_digits(const std::string& text, std::size_t at) {
  while (at < text.size() && is_digit(text[at])) ++at;
  return at;
}

}  // namespace

const char* const whole_number_syntax = "decimal digits only: no sign, space, hex or suffix";
const char* const decimal_syntax = "a decimal number such as 2, 0.5 or 1e-3: no '+', space or hex";

std::optional<std::int64_t> parse_whole_number(const std::string& text, std::int64_t maximum) {
  if (text.empty() || skip_digits(text, 0) != text.size()) return std::nullopt;
  std::int64_t value = 0;
  for (const char c : text) {
    const int digit = c - '0';
    if (value > (maximum - digit) / 10) return std::nullopt;
    value = value * 10 + digit;
  }
  return value;
}

std::optional<double> parse_decimal(const std::string& text, bool allow_minus) {
  std::size_t at = allow_minus && !text.empty() && text[0] == '-' ? 1 : 0;
  const std::size_t integer_end = skip_digits(text, at);
  bool has_digits = integer_end > at;
  at = integer_end;
  if (at < text.size() && text[at] == '.') {
    const std::size_t fraction_end = skip_digits(text, at + 1);
    has_digits = has_digits || fraction_end > at + 1;
    at = fraction_end;
  }
  if (!has_digits) return std::nullopt;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    std::size_t exponent = at + 1;
    if (exponent < text.size() && (text[exponent] == '+' || text[exponent] == '-')) ++exponent;
    const std::size_t exponent_end = skip_digits(text, exponent);
    if (exponent_end == exponent) return std::nullopt;
    at = exponent_end;
  }
  if (at != text.size()) return std::nullopt;
  const double value = std::strtod(text.c_str(), nullptr);
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace impulse2d::demos

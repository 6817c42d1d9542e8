#pragma once
/// @file strict_number.h
/// Numbers as a user writes them on the command line and in scene-file strings, read strictly:
/// plain decimal digits, no spaces, no '+', no hex, no trailing characters. `strtol` and
/// CLI11 accept " 5", "+5" and "0x10"; a size, count, index or scale must not.

#include <cstdint>
#include <optional>
#include <string>

namespace impulse2d::demos {

/// The whole number `text` writes with decimal digits alone ("0", "42"; not "", "+5", " 5",
/// "0x10", "5k", "-1"), or nothing; also nothing when it exceeds `maximum`.
std::optional<std::int64_t> parse_whole_number(const std::string& text,
                                               std::int64_t maximum = INT64_MAX);

/// The finite decimal `text` writes as digits with at most one '.', an optional exponent
/// ("e-3", "E+2") and, when `allow_minus`, one leading '-' ("0.5", "1e3", ".5", "-2");
/// nothing for anything else ("", "+1", " 1", "0x1p3", "inf", "nan", "1,5", "1e999").
std::optional<double> parse_decimal(const std::string& text, bool allow_minus);

/// What `parse_whole_number` accepts, for messages: "digits 0-9 only (no sign, space or hex)".
extern const char* const whole_number_syntax;
/// What `parse_decimal` accepts, for messages.
extern const char* const decimal_syntax;

}  // namespace impulse2d::demos

#pragma once
/// @file option_numbers.h
/// The numbers of `lab` and `tune` options, read strictly (scene/strict_number.h: digits only
/// for a count, a plain finite decimal for a bound) and checked against their range, with a
/// message naming the option, its text and the range.

#include <cstdint>
#include <string>
#include <utility>

namespace impulse2d::lab {

/// The whole number `text` of option `flag` in [minimum, maximum]. Throws `demos::UsageError`
/// "--repeats ' 3': expected a whole number in 1..100 (decimal digits only: ...)".
std::int64_t count_option(const std::string& flag, const std::string& text, std::int64_t minimum,
                          std::int64_t maximum);

/// The finite decimal `text` of option `flag` with minimum < value <= maximum, in `unit`. Throws
/// `demos::UsageError` "--max-error 'inf': expected a number in (0, 1000] m (...)".
double decimal_option(const std::string& flag, const std::string& text, double minimum,
                      double maximum, const std::string& unit);

/// Parses "K/N" (1 <= K <= N <= 10000, digits only). Throws `demos::UsageError` naming --shard.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace impulse2d::lab

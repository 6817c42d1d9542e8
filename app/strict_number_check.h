#pragma once
/// @file strict_number_check.h
/// CLI11 checks that hold an option's text to the strict number syntax of
/// scene/strict_number.h before CLI11 converts it (CLI11's own conversion takes "+5", " 5"
/// and "0x10").

#include <CLI/CLI.hpp>

namespace impulse2d::demos {

/// The option's text is a whole number: decimal digits only (a size, count, index, steps).
CLI::Validator whole_number_check();

/// The option's text is a decimal without a sign (a scale, rate or ratio): "2", "0.5", "1e-3".
CLI::Validator decimal_check();

}  // namespace impulse2d::demos

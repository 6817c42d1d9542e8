#pragma once
/// @file json_number.h
/// Numbers for the JSON the lab writes (through nlohmann::json, which prints a double with the
/// fewest digits that read back to it): a float setting is first written with the fewest
/// digits that read back to the float (0.02f -> 0.02, not 0.0199999996), and a value that is
/// not finite is refused, since JSON has no inf or nan.

#include <string>

namespace impulse2d::lab {

/// The double whose shortest form is the float's shortest form (0.02f -> 0.02). Throws
/// `std::logic_error` naming `field` when `value` is not finite.
double json_number(float value, const std::string& field);

/// `value` itself. Throws `std::logic_error` naming `field` when it is not finite.
double json_number(double value, const std::string& field);

}  // namespace impulse2d::lab

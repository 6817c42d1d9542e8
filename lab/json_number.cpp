/// @file json_number.cpp
#include "lab/json_number.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace impulse2d::lab {

double json_number(float value, const std::string& field) {
  if (!std::isfinite(value)) throw std::logic_error(field + ": not a finite number; JSON cannot hold it");
  char text[64];
  const std::to_chars_result written = std::to_chars(text, text + sizeof text - 1, value);
  *written.ptr = '\0';
  return std::strtod(text, nullptr);
}

double json_number(double value, const std::string& field) {
  if (!std::isfinite(value)) throw std::logic_error(field + ": not a finite number; JSON cannot hold it");
  return value;
}

}  // namespace impulse2d::lab

/// @file strict_number_check.cpp
#include "app/strict_number_check.h"

#include "scene/strict_number.h"

namespace impulse2d::demos {

CLI::Validator whole_number_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parse_whole_number(text)) return "";
        return "'" + text + "' is not a whole number (" + whole_number_syntax + ")";
      },
      "");
}

CLI::Validator decimal_check() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (parse_decimal(text, false)) return "";
        return "'" + text + "' is not a number (" + decimal_syntax + ")";
      },
      "");
}

}  // namespace impulse2d::demos

/// @file params.cpp
#include "scene/params.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/usage_error.h"

namespace impulse2d::demos {

Params::Params(std::vector<ParamSpec> specs) : specs_(std::move(specs)) {
  for (const ParamSpec& each : specs_) values_[each.name] = each.default_value;
}

const ParamSpec& Params::spec(const std::string& name) const {
  for (const ParamSpec& each : specs_) {
    if (each.name == name) return each;
  }
  std::string known;
  for (const ParamSpec& each : specs_) known += (known.empty() ? "" : ", ") + each.name;
  throw UsageError("unknown parameter '" + name + "' (this scene takes: " +
                   (known.empty() ? std::string("no parameters") : known) + ")");
}

void Params::set(const std::string& name, const std::string& text) {
  spec(name);  // unknown names are reported before the value
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || !std::isfinite(value)) {
    throw UsageError("parameter " + name + ": '" + text + "' is not a finite number");
  }
  set(name, value);
}

void Params::set(const std::string& name, double value) {
  const ParamSpec& declared = spec(name);
  if (!std::isfinite(value)) throw UsageError("parameter " + name + ": value is not finite");
  if (declared.integer && std::floor(value) != value) {
    throw UsageError("parameter " + name + ": must be a whole number, got " +
                     format_param_value(value));
  }
  if (value < declared.minimum || value > declared.maximum) {
    throw UsageError("parameter " + name + ": " + format_param_value(value) + " is outside " +
                     format_param_value(declared.minimum) + ".." +
                     format_param_value(declared.maximum));
  }
  values_[name] = value;
}

void Params::set_assignment(const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw UsageError("--param '" + assignment + "': expected key=value, e.g. rows=20");
  }
  set(assignment.substr(0, equals), assignment.substr(equals + 1));
}

double Params::number(const std::string& name) const {
  spec(name);
  return values_.at(name);
}

int Params::integer(const std::string& name) const { return static_cast<int>(number(name)); }

std::string Params::summary() const {
  std::string text;
  for (const ParamSpec& each : specs_) {
    text += (text.empty() ? "" : " ") + each.name + "=" + format_param_value(values_.at(each.name));
  }
  return text;
}

std::string format_param_value(double value) {
  if (std::floor(value) == value && std::fabs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  std::string text;
  for (int digits = 1; digits <= 17; ++digits) {
    std::ostringstream attempt;
    attempt.precision(digits);
    attempt << value;
    text = attempt.str();
    if (std::strtod(text.c_str(), nullptr) == value) break;
  }
  return text;
}

}  // namespace impulse2d::demos

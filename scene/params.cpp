/// @file params.cpp
#include "scene/params.h"

#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "scene/strict_number.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

Params::Params(std::vector<ParamSpec> specs) : specs_(std::move(specs)) {
  for (const ParamSpec& each : specs_) values_[each.name] = each.default_value;
}

const ParamSpec* Params::find(const std::string& name) const {
  for (const ParamSpec& each : specs_) {
    if (each.name == name) return &each;
  }
  return nullptr;
}

const ParamSpec& Params::spec(const std::string& name) const {
  if (const ParamSpec* found = find(name)) return *found;
  throw UsageError(unknown_reason(name));
}

std::string Params::unknown_reason(const std::string& name) const {
  std::string known;
  for (const ParamSpec& each : specs_) known += (known.empty() ? "" : ", ") + each.name;
  return "unknown parameter '" + name + "' (this scene takes: " +
         (known.empty() ? std::string("no parameters") : known) + ")";
}

std::string Params::value_reason(const ParamSpec& declared, double value) {
  if (!std::isfinite(value)) return "the value is not finite";
  if (declared.integer && std::floor(value) != value) {
    return "must be a whole number, got " + format_param_value(value);
  }
  if (value < declared.minimum || value > declared.maximum) {
    return format_param_value(value) + " is outside " + format_param_value(declared.minimum) +
           ".." + format_param_value(declared.maximum);
  }
  return "";
}

void Params::set(const std::string& name, const std::string& text) {
  spec(name);  // unknown names are reported before the value
  const std::optional<double> value = parse_decimal(text, true);
  if (!value) {
    throw UsageError("parameter " + name + ": '" + text + "' is not a number (" + decimal_syntax + ")");
  }
  set(name, *value);
}

void Params::set(const std::string& name, double value) {
  const std::string reason = value_reason(spec(name), value);
  if (!reason.empty()) throw UsageError("parameter " + name + ": " + reason);
  values_[name] = value;
}

void Params::set_assignment(const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw UsageError("--param '" + assignment + "': expected key=value, e.g. rows=20");
  }
  const std::string name = assignment.substr(0, equals);
  const std::string text = assignment.substr(equals + 1);
  const std::string where = "--param " + assignment + ": ";
  const ParamSpec* declared = find(name);
  if (declared == nullptr) throw UsageError(where + unknown_reason(name));
  const std::optional<double> value = parse_decimal(text, true);
  if (!value) {
    throw UsageError(where + "'" + text + "' is not a number (" + decimal_syntax + ")");
  }
  const std::string reason = value_reason(*declared, *value);
  if (!reason.empty()) throw UsageError(where + "parameter " + name + ": " + reason);
  values_[name] = *value;
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

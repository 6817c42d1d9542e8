/// @file json_fields.cpp
#include "golden/json_fields.h"

#include "golden/error.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace impulse2d::golden {

using nlohmann::json;

FieldReader::FieldReader(const json& object, std::string origin, std::string prefix)
    : object_(object), origin_(std::move(origin)), prefix_(std::move(prefix)) {
  if (!object_.is_object()) {
    const std::string where =
        prefix_.empty() ? "top level" : "field '" + prefix_.substr(0, prefix_.size() - 1) + "'";
    throw GoldenError(origin_ + ": " + where + ": expected a JSON object, got " + object_.dump());
  }
}

void FieldReader::fail(const std::string& field, const std::string& reason) const {
  throw GoldenError(origin_ + ": field '" + prefix_ + field + "': " + reason);
}

const json& FieldReader::get(const std::string& field) const {
  if (!object_.contains(field)) fail(field, "missing");
  return object_.at(field);
}

std::string FieldReader::string(const std::string& field, bool allow_empty) const {
  const json& value = get(field);
  if (!value.is_string()) fail(field, "expected a string, got " + value.dump());
  std::string text = value.get<std::string>();
  if (!allow_empty && text.empty()) fail(field, "must not be empty");
  return text;
}

int FieldReader::integer(const std::string& field, int minimum) const {
  const json& value = get(field);
  if (!value.is_number_integer()) fail(field, "expected an integer, got " + value.dump());
  const auto number = value.get<std::int64_t>();
  if (number < minimum || number > std::numeric_limits<int>::max()) {
    fail(field, value.dump() + " is out of range (minimum " + std::to_string(minimum) + ")");
  }
  return static_cast<int>(number);
}

double FieldReader::number(const std::string& field) const {
  const json& value = get(field);
  if (!value.is_number()) fail(field, "expected a number, got " + value.dump());
  const double number = value.get<double>();
  if (!std::isfinite(number)) fail(field, "must be finite");
  return number;
}

double FieldReader::non_negative(const std::string& field) const {
  const double value = number(field);
  if (value < 0.0) fail(field, "must be >= 0, got " + get(field).dump());
  return value;
}

const json& FieldReader::array(const std::string& field) const {
  const json& value = get(field);
  if (!value.is_array()) fail(field, "expected an array, got " + value.dump());
  return value;
}

void FieldReader::reject_unknown(const std::set<std::string>& known) const {
  for (const auto& item : object_.items()) {
    if (known.count(item.key()) == 0) fail(item.key(), "unknown field");
  }
}

}  // namespace impulse2d::golden

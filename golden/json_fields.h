#pragma once
/// @file json_fields.h
/// Validated reads of one JSON object's fields, for the golden files (sidecars, noise
/// envelopes): every access checks presence, type and range, and errors name the file and
/// the field's path.

#include <nlohmann/json.hpp>

#include <set>
#include <string>

namespace impulse2d::golden {

/// Reads fields of one JSON object; every error is a `GoldenError` "<origin>: field
/// '<prefix><field>': <reason>".
class FieldReader {
 public:
  /// Reads `object`, which must be a JSON object; `prefix` is the path to it with a trailing
  /// dot ("renderer."), empty at the top level. Throws `GoldenError` when it is not an object.
  FieldReader(const nlohmann::json& object, std::string origin, std::string prefix);

  /// Throws the error for `field` with `reason`.
  [[noreturn]] void fail(const std::string& field, const std::string& reason) const;
  /// True when the object has `field`.
  bool has(const std::string& field) const { return object_.contains(field); }
  /// The value of `field`; throws when it is missing.
  const nlohmann::json& get(const std::string& field) const;
  /// A string field; throws when missing, not a string, or empty unless `allow_empty`.
  std::string string(const std::string& field, bool allow_empty) const;
  /// An integer field in minimum..INT_MAX.
  int integer(const std::string& field, int minimum) const;
  /// A finite number field.
  double number(const std::string& field) const;
  /// A finite number field that is >= 0.
  double non_negative(const std::string& field) const;
  /// An array field.
  const nlohmann::json& array(const std::string& field) const;
  /// Throws for the first field not in `known`.
  void reject_unknown(const std::set<std::string>& known) const;

 private:
  const nlohmann::json& object_;
  std::string origin_;
  std::string prefix_;
};

}  // namespace impulse2d::golden

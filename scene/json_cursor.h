#pragma once
/// @file json_cursor.h
/// Validated reading of a JSON document: every read knows its JSON path
/// (e.g. `bodies[3].shape.radius`), and every failure throws `UsageError` with
/// "<file>: <path>: <reason>".

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"

namespace impulse2d::demos {

/// A JSON value together with the file it came from and its path in the document.
class JsonCursor {
 public:
  /// The document root of `file`.
  JsonCursor(const nlohmann::json& value, std::string file);

  /// The JSON path, e.g. "bodies[3].shape"; "(root)" for the document itself.
  std::string path() const;
  /// The value itself.
  const nlohmann::json& value() const { return *value_; }

  /// Throws `UsageError` "<file>: <path>: <reason>".
  [[noreturn]] void fail(const std::string& reason) const;

  /// Fails unless this is an object.
  void expect_object() const;
  /// True when this is an object holding `key`.
  bool has(const std::string& key) const;
  /// The member `key` of this object; fails when this is not an object or `key` is missing.
  JsonCursor field(const std::string& key) const;
  /// The member `key`, or nothing when it is absent (fails when this is not an object).
  std::optional<JsonCursor> optional_field(const std::string& key) const;
  /// Fails naming the first member whose key is not in `known` (catches misspellings).
  void allow_only(const std::vector<const char*>& known) const;
  /// Number of elements; fails unless this is an array.
  std::size_t size() const;
  /// Element `index` of this array.
  JsonCursor element(std::size_t index) const;

  /// A finite number that fits a float.
  float real() const;
  /// A finite number > 0.
  float positive() const;
  /// A finite number >= 0.
  float non_negative() const;
  /// A number in [minimum, maximum]; the failure names the range and `why` it is the range.
  float in_range(float minimum, float maximum, const std::string& why) const;
  /// A number in [-maximum, maximum]; the failure names the range and `why`.
  float magnitude_at_most(float maximum, const std::string& why) const;
  /// [x, y] with each component in [-maximum, maximum]; the failure names the range and `why`.
  vec2 vector_at_most(float maximum, const std::string& why) const;
  /// A whole number in [minimum, maximum].
  std::int64_t integer(std::int64_t minimum, std::int64_t maximum) const;
  /// true or false.
  bool boolean() const;
  /// A string.
  std::string string() const;
  /// A 2-element array of finite numbers [x, y].
  vec2 vector() const;
  /// A string that is one of `choices`' names; returns the matching value.
  template <typename T>
  T choice(const std::vector<std::pair<const char*, T>>& choices) const {
    const std::string text = string();
    std::string known;
    for (const auto& [name, value] : choices) {
      if (text == name) return value;
      known += (known.empty() ? "" : ", ") + std::string(name);
    }
    fail("unknown value \"" + text + "\" (expected one of: " + known + ")");
  }

 private:
  JsonCursor(const nlohmann::json& value, std::string file, std::string path);
  [[noreturn]] void fail_type(const char* expected) const;

  const nlohmann::json* value_;
  std::string file_;
  std::string path_;  // empty at the root
};

/// Parses `text` (the contents of `file`). Throws `UsageError` "<file>: <path>: malformed
/// JSON: <reason> at line L, column C" naming the JSON path where parsing stopped (which
/// also catches NaN, Infinity and numbers too large for a double), and "<file>: <path>:
/// duplicate key" when an object repeats a key.
nlohmann::json parse_json_document(const std::string& text, const std::string& file);

/// `value` in printf's %g form ("0.001", "1e+06") for messages.
std::string compact_number(double value);

/// "string \"abc\"", "number 3", "object", ... for messages.
std::string describe_json_value(const nlohmann::json& value);

}  // namespace impulse2d::demos

/// @file json_cursor.cpp
#include "scene/json_cursor.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

#include "scene/usage_error.h"

namespace impulse2d::demos {

using nlohmann::json;

JsonCursor::JsonCursor(const json& value, std::string file)
    : JsonCursor(value, std::move(file), "") {}

JsonCursor::JsonCursor(const json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

std::string JsonCursor::path() const { return path_.empty() ? "(root)" : path_; }

void JsonCursor::fail(const std::string& reason) const {
  throw UsageError(file_ + ": " + path() + ": " + reason);
}

void JsonCursor::fail_type(const char* expected) const {
  fail(std::string("expected ") + expected + ", got " + describe_json_value(*value_));
}

void JsonCursor::expect_object() const {
  if (!value_->is_object()) fail_type("an object");
}

bool JsonCursor::has(const std::string& key) const {
  return value_->is_object() && value_->contains(key);
}

JsonCursor JsonCursor::field(const std::string& key) const {
  expect_object();
  const auto found = value_->find(key);
  if (found == value_->end()) fail("missing field \"" + key + "\"");
  return JsonCursor(*found, file_, path_.empty() ? key : path_ + "." + key);
}

std::optional<JsonCursor> JsonCursor::optional_field(const std::string& key) const {
  expect_object();
  if (!value_->contains(key)) return std::nullopt;
  return field(key);
}

void JsonCursor::allow_only(const std::vector<const char*>& known) const {
  expect_object();
  for (const auto& member : value_->items()) {
    bool found = false;
    for (const char* name : known) found = found || member.key() == name;
    if (found) continue;
    std::string list;
    for (const char* name : known) list += (list.empty() ? "" : ", ") + std::string(name);
    fail("unknown field \"" + member.key() + "\" (allowed: " + list + ")");
  }
}

std::size_t JsonCursor::size() const {
  if (!value_->is_array()) fail_type("an array");
  return value_->size();
}

JsonCursor JsonCursor::element(std::size_t index) const {
  if (index >= size()) fail("has no element " + std::to_string(index));
  return JsonCursor((*value_)[index], file_, path_ + "[" + std::to_string(index) + "]");
}

float JsonCursor::real() const {
  if (!value_->is_number()) fail_type("a number");
  const double number = value_->get<double>();
  if (!std::isfinite(number)) fail("must be finite, got " + value_->dump());
  if (std::fabs(number) > std::numeric_limits<float>::max()) {
    fail("must fit a float (|x| <= 3.4e38), got " + value_->dump());
  }
  return static_cast<float>(number);
}

float JsonCursor::positive() const {
  const float number = real();
  if (!(number > 0.0f)) fail("must be > 0, got " + value_->dump());
  return number;
}

float JsonCursor::in_range(float minimum, float maximum, const std::string& why) const {
  const float number = real();
  if (!(number >= minimum && number <= maximum)) {
    fail("must be in " + compact_number(minimum) + ".." + compact_number(maximum) + " (" + why +
         "), got " + value_->dump());
  }
  return number;
}

float JsonCursor::magnitude_at_most(float maximum, const std::string& why) const {
  return in_range(-maximum, maximum, why);
}

vec2 JsonCursor::vector_at_most(float maximum, const std::string& why) const {
  if (!value_->is_array() || value_->size() != 2) fail_type("[x, y] (an array of 2 numbers)");
  return vec2(element(0).magnitude_at_most(maximum, why),
              element(1).magnitude_at_most(maximum, why));
}

std::string compact_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

float JsonCursor::non_negative() const {
  const float number = real();
  if (!(number >= 0.0f)) fail("must be >= 0, got " + value_->dump());
  return number;
}

std::int64_t JsonCursor::integer(std::int64_t minimum, std::int64_t maximum) const {
  const std::string range = std::to_string(minimum) + ".." + std::to_string(maximum);
  if (!value_->is_number_integer()) fail_type(("a whole number in " + range).c_str());
  const bool negative = value_->is_number_unsigned() ? false : value_->get<std::int64_t>() < 0;
  if (!negative && value_->get<std::uint64_t>() > static_cast<std::uint64_t>(maximum)) {
    fail("must be in " + range + ", got " + value_->dump());
  }
  const std::int64_t number = value_->get<std::int64_t>();
  if (number < minimum || number > maximum) fail("must be in " + range + ", got " + value_->dump());
  return number;
}

bool JsonCursor::boolean() const {
  if (!value_->is_boolean()) fail_type("true or false");
  return value_->get<bool>();
}

std::string JsonCursor::string() const {
  if (!value_->is_string()) fail_type("a string");
  return value_->get<std::string>();
}

vec2 JsonCursor::vector() const {
  if (!value_->is_array() || value_->size() != 2) fail_type("[x, y] (an array of 2 numbers)");
  return vec2(element(0).real(), element(1).real());
}

std::string describe_json_value(const json& value) {
  switch (value.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array of " + std::to_string(value.size());
    case json::value_t::string:
      return "string " + value.dump();
    case json::value_t::boolean:
      return value.dump();
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float:
      return "number " + value.dump();
    default:
      return "a value of another kind";
  }
}

namespace {

/// A SAX handler that only tracks the JSON path, so a parse error can be reported where it
/// happened (nlohmann's DOM parser gives the byte position alone).
class PathTracker : public nlohmann::json_sax<json> {
 public:
  /// Tracks the parse of `file` (named in the duplicate-key error).
  explicit PathTracker(std::string file) : file_(std::move(file)) {}
  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& name) override {
    levels_.back().key = name;
    // nlohmann keeps the last of two equal keys: "radius": -1, "radius": 1 would pass.
    if (!levels_.back().keys.insert(name).second) {
      throw UsageError(file_ + ": " + current_path() + ": duplicate key \"" + name +
                       "\" (a key may appear once per object)");
    }
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t position, const std::string&,
                   const nlohmann::detail::exception& error) override {
    error_position_ = position;
    error_message_ = error.what();
    error_path_ = current_path();
    return false;
  }

  /// Byte offset (1-based as nlohmann counts) where parsing stopped.
  std::size_t error_position() const { return error_position_; }
  /// nlohmann's message.
  const std::string& error_message() const { return error_message_; }
  /// The path of the value being read when parsing stopped.
  const std::string& error_path() const { return error_path_; }

 private:
  struct Level {
    bool array = false;
    std::size_t started = 0;  // elements begun so far (arrays)
    std::string key;          // the member being read (objects)
    std::set<std::string> keys;  // every key seen so far (objects)
  };
  bool value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().started;
    return true;
  }
  bool open(bool array) {
    value();
    levels_.push_back(Level{array, 0, "", {}});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return true;
  }
  std::string current_path() const {
    std::string path;
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      const Level& level = levels_[i];
      const bool innermost = i + 1 == levels_.size();
      if (level.array) {
        // An enclosing array holds the element being read; the innermost one fails on the
        // element after the last one that started.
        const std::size_t index = innermost ? level.started : level.started - 1;
        path += "[" + std::to_string(index) + "]";
      } else if (!level.key.empty()) {
        path += (path.empty() ? "" : ".") + level.key;
      }
    }
    return path.empty() ? "(root)" : path;
  }

  std::string file_;
  std::vector<Level> levels_;
  std::size_t error_position_ = 0;
  std::string error_message_;
  std::string error_path_;
};

/// nlohmann's message without its "[json.exception.kind.N] " prefix and its own position
/// (given separately as line and column).
std::string plain_message(std::string message) {
  if (!message.empty() && message.front() == '[') {
    const std::size_t end = message.find("] ");
    if (end != std::string::npos) message.erase(0, end + 2);
  }
  const std::size_t at = message.find("parse error at line ");
  if (at == 0) {
    const std::size_t colon = message.find(": ");
    if (colon != std::string::npos) message.erase(0, colon + 2);
  }
  return message;
}

}  // namespace

json parse_json_document(const std::string& text, const std::string& file) {
  PathTracker tracker(file);
  if (!json::sax_parse(text, &tracker)) {
    // nlohmann counts the byte that stopped it, 1-based; locate it in lines and columns.
    const std::size_t stop =
        std::min(tracker.error_position() == 0 ? 0 : tracker.error_position() - 1, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < stop; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw UsageError(file + ": " + tracker.error_path() + ": malformed JSON at line " +
                     std::to_string(line) + ", column " + std::to_string(column) + ": " +
                     plain_message(tracker.error_message()));
  }
  return json::parse(text);
}

}  // namespace impulse2d::demos

/// @file script_state.cpp
#include "scene/script_state.h"

#include <cmath>
#include <cstring>
#include <utility>

#include "core/error.h"

namespace impulse2d::demos {

ScriptStateWriter::ScriptStateWriter(std::uint32_t version) { u32(version); }

void ScriptStateWriter::boolean(bool value) { u8(value ? 1u : 0u); }

void ScriptStateWriter::u8(std::uint8_t value) { bytes_.push_back(value); }

void ScriptStateWriter::u32(std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
}

void ScriptStateWriter::i32(std::int32_t value) { u32(static_cast<std::uint32_t>(value)); }

void ScriptStateWriter::f32(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, 4);
  u32(bits);
}

void ScriptStateWriter::vector(vec2 value) {
  f32(value.x);
  f32(value.y);
}

void ScriptStateWriter::body(BodyId value) {
  u32(value.index);
  u32(value.generation);
}

void ScriptStateWriter::nested(const std::vector<std::uint8_t>& bytes) {
  u32(static_cast<std::uint32_t>(bytes.size()));
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
}

ScriptStateReader::ScriptStateReader(const std::vector<std::uint8_t>& bytes, std::string script,
                                     std::uint32_t version)
    : bytes_(bytes), script_(std::move(script)) {
  const std::uint32_t saved = u32();
  if (saved != version) {
    fail("layout version " + std::to_string(saved) + "; this impulse2d reads version " +
         std::to_string(version));
  }
}

const std::uint8_t* ScriptStateReader::take(std::size_t count) {
  if (count > bytes_.size() - at_) {
    fail("the state ends early (" + std::to_string(bytes_.size()) + " bytes)");
  }
  const std::uint8_t* data = bytes_.data() + at_;
  at_ += count;
  return data;
}

bool ScriptStateReader::boolean() { return u8(1u) == 1u; }

std::uint8_t ScriptStateReader::u8(std::uint8_t largest) {
  const std::uint8_t value = *take(1);
  if (value > largest) {
    --at_;
    fail("value " + std::to_string(value) + " out of range 0.." + std::to_string(largest));
  }
  return value;
}

std::uint32_t ScriptStateReader::u32() {
  const std::uint8_t* data = take(4);
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value |= static_cast<std::uint32_t>(data[i]) << (8 * i);
  return value;
}

std::int32_t ScriptStateReader::i32(std::int32_t smallest, std::int32_t largest) {
  const std::int32_t value = static_cast<std::int32_t>(u32());
  if (value < smallest || value > largest) {
    at_ -= 4;
    fail("value " + std::to_string(value) + " out of range " + std::to_string(smallest) + ".." +
         std::to_string(largest));
  }
  return value;
}

float ScriptStateReader::f32() {
  const std::uint32_t bits = u32();
  float value = 0.0f;
  std::memcpy(&value, &bits, 4);
  if (!std::isfinite(value)) {
    at_ -= 4;
    fail("a number that is not finite");
  }
  return value;
}

vec2 ScriptStateReader::vector() {
  const float x = f32();
  return vec2(x, f32());
}

BodyId ScriptStateReader::body() {
  BodyId id;
  id.index = u32();
  id.generation = u32();
  return id;
}

std::vector<std::uint8_t> ScriptStateReader::nested() {
  const std::uint32_t count = u32();
  const std::uint8_t* data = take(count);
  return std::vector<std::uint8_t>(data, data + count);
}

void ScriptStateReader::finish() const {
  if (at_ != bytes_.size()) {
    fail(std::to_string(bytes_.size() - at_) + " bytes left over after the state");
  }
}

void ScriptStateReader::fail(const std::string& what) const {
  throw Error(script_ + " state, byte " + std::to_string(at_) + ": " + what);
}

}  // namespace impulse2d::demos

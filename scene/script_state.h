#pragma once
/// @file script_state.h
/// A step script's state as bytes (`StepScript::save_state`): a u32 layout version of the
/// script's own, then its fields, every number little-endian, floats as their IEEE-754 bits,
/// body handles as u32 index + u32 generation, nested states as a u32 byte count + bytes.

#include <cstdint>
#include <string>
#include <vector>

#include "core/body.h"
#include "core/math.h"

namespace impulse2d::demos {

/// Appends a script's fields to bytes, after its layout version.
class ScriptStateWriter {
 public:
  /// Starts the bytes with `version`, the layout version of the script writing them.
  explicit ScriptStateWriter(std::uint32_t version);
  /// A bool as one byte, 0 or 1.
  void boolean(bool value);
  /// One byte.
  void u8(std::uint8_t value);
  /// Four bytes.
  void u32(std::uint32_t value);
  /// Four bytes, two's complement.
  void i32(std::int32_t value);
  /// The float's four bytes of IEEE-754 bits.
  void f32(float value);
  /// x then y.
  void vector(vec2 value);
  /// Slot index then generation (a null handle is index 0xFFFFFFFF).
  void body(BodyId value);
  /// Another script's bytes (e.g. a base class's), after their byte count.
  void nested(const std::vector<std::uint8_t>& bytes);
  /// The bytes written so far.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
};

/// Reads what a `ScriptStateWriter` wrote. Every read throws `Error` naming the script and the
/// byte where the bytes end early or hold a value no writer writes (a bool other than 0 or 1,
/// a float that is not finite, an enum out of range); nothing is read past the end.
class ScriptStateReader {
 public:
  /// Reads the layout version first; throws `Error` unless it is `version`. `script` names the
  /// script in messages ("script tutorial").
  ScriptStateReader(const std::vector<std::uint8_t>& bytes, std::string script, std::uint32_t version);
  /// A bool written by `boolean`.
  bool boolean();
  /// A byte no larger than `largest` (enums as their underlying value).
  std::uint8_t u8(std::uint8_t largest = 0xFFu);
  /// Four bytes.
  std::uint32_t u32();
  /// A value written by `i32` in [`smallest`, `largest`].
  std::int32_t i32(std::int32_t smallest = INT32_MIN, std::int32_t largest = INT32_MAX);
  /// A finite float.
  float f32();
  /// Two finite floats.
  vec2 vector();
  /// A body handle (null, or any index and generation: the caller checks it against its world).
  BodyId body();
  /// Bytes written by `nested`.
  std::vector<std::uint8_t> nested();
  /// Throws `Error` when bytes are left over (they belong to another layout).
  void finish() const;
  /// Throws `Error` naming the script, the current byte and `what` (for the caller's own
  /// checks of values against its world).
  [[noreturn]] void fail(const std::string& what) const;

 private:
  const std::uint8_t* take(std::size_t count);
  const std::vector<std::uint8_t>& bytes_;
  std::string script_;
  std::size_t at_ = 0;
};

}  // namespace impulse2d::demos

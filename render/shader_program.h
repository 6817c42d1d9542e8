#pragma once
/// @file shader_program.h
/// A linked GLSL program (vertex + fragment), with compile and link errors as exceptions.

#include <string>

namespace impulse2d::render {

/// Owns one GL program object. Needs a current GL context for its whole life.
class ShaderProgram {
 public:
  /// Compiles and links the two stages. Throws `RenderError` naming `name`, the stage and
  /// the driver's info log when either fails.
  ShaderProgram(const std::string& name, const char* vertex_source, const char* fragment_source);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  /// Makes this the current program.
  void use() const;
  /// Location of the active uniform `uniform_name`. Throws `RenderError` when the program
  /// has no such active uniform.
  int uniform_location(const char* uniform_name) const;

 private:
  std::string name_;
  unsigned int program_ = 0;
};

}  // namespace impulse2d::render

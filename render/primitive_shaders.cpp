/// @file primitive_shaders.cpp
#include "render/primitive_shaders.h"

namespace impulse2d::render {

const char* const primitive_vertex_shader = R"glsl(#version 330 core
layout(location = 0) in vec2 a_position;  // window pixels, origin bottom-left
layout(location = 1) in vec2 a_local;     // pixels from the primitive's centre, in its frame
layout(location = 2) in vec2 a_extent;    // see primitive_shaders.h
layout(location = 3) in vec4 a_color;

uniform vec2 u_viewport;  // pixels

out vec2 v_local;
flat out vec2 v_extent;
flat out vec4 v_color;

void main() {
  v_local = a_local;
  v_extent = a_extent;
  v_color = a_color;
  gl_Position = vec4(a_position / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
)glsl";

const char* const primitive_fragment_shader = R"glsl(#version 330 core
in vec2 v_local;
flat in vec2 v_extent;
flat in vec4 v_color;

out vec4 o_color;

void main() {
  float coverage;
  if (v_extent.x < 0.0) {
    float radius = -v_extent.x;
    float distance = length(v_local);
    coverage = clamp(radius + 0.5 - distance, 0.0, 1.0);
    if (v_extent.y > 0.0) coverage *= clamp(distance - (radius - v_extent.y) + 0.5, 0.0, 1.0);
  } else {
    vec2 inside = clamp(v_extent + 0.5 - abs(v_local), 0.0, 1.0);
    coverage = inside.x * inside.y;
  }
  if (coverage <= 0.0) discard;
  o_color = vec4(v_color.rgb, v_color.a * coverage);
}
)glsl";

}  // namespace impulse2d::render

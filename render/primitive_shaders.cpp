/// @file primitive_shaders.cpp
#include "render/primitive_shaders.h"

namespace impulse2d::render {

const char* const primitive_vertex_shader = R"glsl(#version 330 core
layout(location = 0) in vec2 a_p0;
layout(location = 1) in vec2 a_p1;
layout(location = 2) in vec2 a_p2;
layout(location = 3) in vec2 a_params;
layout(location = 4) in vec4 a_color;
layout(location = 5) in uint a_kind;

uniform mat4 u_world_to_clip;
uniform vec2 u_viewport;  // pixels

out vec4 v_color;
out vec2 v_local;         // pixels, relative to the primitive's centre
flat out vec2 v_extent;   // segment half length and half width, or disc radius and ring width
flat out uint v_kind;

// Two triangles covering the unit square.
const vec2 corners[6] = vec2[6](vec2(0.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 1.0),
                                vec2(0.0, 0.0), vec2(1.0, 1.0), vec2(0.0, 1.0));

vec2 to_pixel(vec2 world) {
  vec4 clip = u_world_to_clip * vec4(world, 0.0, 1.0);
  return (clip.xy * 0.5 + 0.5) * u_viewport;
}

void main() {
  vec2 corner = corners[gl_VertexID];
  vec2 pixel = vec2(0.0);
  v_local = vec2(0.0);
  v_extent = vec2(0.0);
  if (a_kind == 0u) {
    pixel = to_pixel(gl_VertexID == 0 ? a_p0 : (gl_VertexID == 1 ? a_p1 : a_p2));
  } else if (a_kind == 1u) {
    pixel = to_pixel(a_p0 + corner.x * (a_p1 - a_p0) + corner.y * (a_p2 - a_p1));
  } else if (a_kind == 2u) {
    vec2 a = to_pixel(a_p0);
    vec2 b = to_pixel(a_p1);
    float len = length(b - a);
    vec2 dir = len > 1e-6 ? (b - a) / len : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);
    v_extent = vec2(0.5 * len + a_params.y, a_params.x);
    vec2 reach = v_extent + 1.0;  // one pixel of room for the anti-aliased edge
    v_local = (corner * 2.0 - 1.0) * reach;
    pixel = 0.5 * (a + b) + dir * v_local.x + normal * v_local.y;
  } else if (a_kind == 3u) {
    v_extent = a_params;
    v_local = (corner * 2.0 - 1.0) * (a_params.x + 1.0);
    pixel = to_pixel(a_p0) + v_local;
  } else if (a_kind == 4u) {
    pixel = floor(to_pixel(a_p0) + 0.5) + mix(a_p1, a_p2, corner);
  } else {
    pixel = mix(a_p1, a_p2, corner);
  }
  v_color = a_color;
  v_kind = a_kind;
  gl_Position = vec4(pixel / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
)glsl";

const char* const primitive_fragment_shader = R"glsl(#version 330 core
in vec4 v_color;
in vec2 v_local;
flat in vec2 v_extent;
flat in uint v_kind;

out vec4 o_color;

void main() {
  float coverage = 1.0;
  if (v_kind == 2u) {
    vec2 inside = clamp(v_extent + 0.5 - abs(v_local), 0.0, 1.0);
    coverage = inside.x * inside.y;
  } else if (v_kind == 3u) {
    float distance = length(v_local);
    coverage = clamp(v_extent.x + 0.5 - distance, 0.0, 1.0);
    if (v_extent.y > 0.0) {
      coverage *= clamp(distance - (v_extent.x - v_extent.y) + 0.5, 0.0, 1.0);
    }
  }
  if (coverage <= 0.0) discard;
  o_color = vec4(v_color.rgb, v_color.a * coverage);
}
)glsl";

}  // namespace impulse2d::render

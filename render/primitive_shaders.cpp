/// @file primitive_shaders.cpp
#include "render/primitive_shaders.h"

namespace impulse2d::render {

namespace {

const char* const shape_vertex_shader = R"glsl(#version 330 core
layout(location = 0) in vec3 a_sprite;  // window position (origin bottom-left), point size
layout(location = 1) in vec4 a_frame;
layout(location = 2) in vec4 a_box;
layout(location = 3) in vec4 a_head;
layout(location = 4) in vec3 a_disc;
layout(location = 5) in vec4 a_fill;
layout(location = 6) in vec4 a_line;

uniform vec2 u_viewport;  // pixels

flat out vec4 v_frame;
flat out vec4 v_box;
flat out vec4 v_head;
flat out vec3 v_disc;
flat out vec4 v_fill;
flat out vec4 v_line;

void main() {
  v_frame = a_frame;
  v_box = a_box;
  v_head = a_head;
  v_disc = a_disc;
  v_fill = a_fill;
  v_line = a_line;
  gl_PointSize = a_sprite.z;
  gl_Position = vec4(a_sprite.xy / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
)glsl";

const char* const polygon_vertex_shader = R"glsl(#version 330 core
layout(location = 0) in vec3 a_sprite;  // window position (origin bottom-left), point size
layout(location = 1) in vec3 a_origin;
layout(location = 2) in vec4 a_fill;
layout(location = 3) in vec4 a_line;
layout(location = 4) in vec3 a_edges[8];

uniform vec2 u_viewport;  // pixels

flat out vec3 v_origin;
flat out vec4 v_fill;
flat out vec4 v_line;
flat out vec3 v_edges[8];

void main() {
  v_origin = a_origin;
  v_fill = a_fill;
  v_line = a_line;
  v_edges = a_edges;
  gl_PointSize = a_sprite.z;
  gl_Position = vec4(a_sprite.xy / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
)glsl";

const char* const polygon_fragment_shader = R"glsl(#version 330 core
flat in vec3 v_origin;
flat in vec4 v_fill;
flat in vec4 v_line;
flat in vec3 v_edges[8];

out vec4 o_color;

void main() {
  vec2 p = gl_FragCoord.xy - v_origin.xy;
  float distance = dot(v_edges[0].xy, p) - v_edges[0].z;
  for (int i = 1; i < 8; ++i) distance = max(distance, dot(v_edges[i].xy, p) - v_edges[i].z);
  // The fill under the outline, which is centred on the edges.
  float fill_alpha = v_fill.a * clamp(0.5 - distance, 0.0, 1.0);
  float line_alpha = v_line.a * clamp(v_origin.z + 0.5 - abs(distance), 0.0, 1.0);
  float under = fill_alpha * (1.0 - line_alpha);
  o_color = vec4(v_line.rgb * line_alpha + v_fill.rgb * under, line_alpha + under);
}
)glsl";

const char* const text_vertex_shader = R"glsl(#version 330 core
layout(location = 0) in vec3 a_sprite;  // window position (origin bottom-left), point size
layout(location = 1) in vec4 a_run;
layout(location = 2) in float a_font_scale;
layout(location = 3) in vec4 a_fill;
layout(location = 4) in uvec4 a_bits_low;
layout(location = 5) in uvec4 a_bits_high;

uniform vec2 u_viewport;  // pixels

flat out vec4 v_run;
flat out float v_font_scale;
flat out vec4 v_fill;
flat out uvec4 v_bits_low;
flat out uvec4 v_bits_high;

void main() {
  v_run = a_run;
  v_font_scale = a_font_scale;
  v_fill = a_fill;
  v_bits_low = a_bits_low;
  v_bits_high = a_bits_high;
  gl_PointSize = a_sprite.z;
  gl_Position = vec4(a_sprite.xy / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
)glsl";

const char* const text_fragment_shader = R"glsl(#version 330 core
flat in vec4 v_run;
flat in float v_font_scale;
flat in vec4 v_fill;
flat in uvec4 v_bits_low;
flat in uvec4 v_bits_high;

out vec4 o_color;

const int kGlyphRows = 9;  // font_glyph_rows

void main() {
  // The pixel centre from the run's top-left corner (y down), and the font pixel under it.
  vec2 q = vec2(gl_FragCoord.x - v_run.x, v_run.y - gl_FragCoord.y);
  vec2 inside = clamp(min(q, v_run.zw - q) + 0.5, 0.0, 1.0);
  ivec2 cell = min(ivec2(q * v_font_scale), ivec2(31, kGlyphRows - 1));
  int bit = clamp(cell.x * kGlyphRows + cell.y, 0, 255);
  uvec4 words = bit < 128 ? v_bits_low : v_bits_high;
  int index = (bit >> 5) & 3;
  uint word = index == 0 ? words.x : index == 1 ? words.y : index == 2 ? words.z : words.w;
  float alpha = v_fill.a * inside.x * inside.y * float((word >> uint(bit & 31)) & 1u);
  o_color = vec4(v_fill.rgb * alpha, alpha);
}
)glsl";

// The body shared by the kinds but polygon and text; KIND selects the shape (the linker drops the inputs a
// kind does not read, so the vertex stage stops passing them on).
const char* const fragment_body = R"glsl(
flat in vec4 v_frame;
flat in vec4 v_box;
flat in vec4 v_head;
flat in vec3 v_disc;
flat in vec4 v_fill;
flat in vec4 v_line;

out vec4 o_color;

// Coverage of the rectangle with half extents `half_extents` centred on the origin at `p`.
float rectangle(vec2 p, vec2 half_extents) {
  vec2 inside = clamp(half_extents + 0.5 - abs(p), 0.0, 1.0);
  return inside.x * inside.y;
}

void main() {
#if KIND == 1  // solid
  o_color = vec4(v_fill.rgb * v_fill.a, v_fill.a);
#else
  vec2 d = gl_FragCoord.xy - v_frame.xy;
  vec2 p = vec2(dot(d, v_frame.zw), v_frame.z * d.y - v_frame.w * d.x);
#if KIND == 2  // disc: the fill under the ring
  float r = length(p);
  float disc = clamp(v_disc.x + 0.5 - r, 0.0, 1.0);
  float ring = clamp(v_disc.y + 0.5 - r, 0.0, 1.0) * clamp(r - v_disc.z + 0.5, 0.0, 1.0);
  float fill_alpha = v_fill.a * disc;
  float line_alpha = v_line.a * ring;
  float under = fill_alpha * (1.0 - line_alpha);
  o_color = vec4(v_line.rgb * line_alpha + v_fill.rgb * under, line_alpha + under);
#else
#if KIND == 3  // box: a filled rectangle, or its outline v_box.w wide when that is > 0
  float coverage = rectangle(p, v_box.xy);
  if (v_box.w > 0.0) coverage -= rectangle(p, v_box.xy - v_box.w);
#else  // arrow
  float side = (p.x - v_head.y) * v_head.z + abs(p.y) * v_head.w;
  float head = clamp(0.5 - max(max(v_head.x - p.x, p.x - v_head.y), side), 0.0, 1.0);
  float coverage = max(rectangle(p, v_box.xy), head);
#endif
  float alpha = v_fill.a * coverage;
  o_color = vec4(v_fill.rgb * alpha, alpha);
#endif
#endif
}
)glsl";

}  // namespace

const char* primitive_vertex_shader(PrimitiveKind kind) {
  if (kind == PrimitiveKind::polygon) return polygon_vertex_shader;
  return kind == PrimitiveKind::text ? text_vertex_shader : shape_vertex_shader;
}

std::string primitive_fragment_shader(PrimitiveKind kind) {
  if (kind == PrimitiveKind::polygon) return polygon_fragment_shader;
  if (kind == PrimitiveKind::text) return text_fragment_shader;
  return "#version 330 core\n#define KIND " + std::to_string(static_cast<int>(kind)) + "\n" + fragment_body;
}

}  // namespace impulse2d::render

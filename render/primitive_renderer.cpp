/// @file primitive_renderer.cpp
#include "render/primitive_renderer.h"

#include "render/gl_api.h"
#include "render/primitive_shaders.h"
#include "render/render_error.h"
#include "render/shader_program.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace impulse2d::render {

namespace {

std::uint8_t to_byte(float channel) {
  const float clamped = std::min(std::max(channel, 0.0f), 1.0f);
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
}

std::uint32_t kind_value(PrimitiveKind kind) { return static_cast<std::uint32_t>(kind); }

// True when the four corners form a parallelogram (boxes do), so one instance draws them.
bool is_parallelogram(const vec2* v) {
  const vec2 gap = (v[0] + v[2]) - (v[1] + v[3]);
  const vec2 size = glm::abs(v[2] - v[0]) + glm::abs(v[3] - v[1]);
  return std::fabs(gap.x) + std::fabs(gap.y) <= 1e-6f * (size.x + size.y);
}

std::string hex(unsigned value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%04X", value);
  return text;
}

}  // namespace

PrimitiveRenderer::PrimitiveRenderer(const PrimitiveStyle& style)
    : style_(style), camera_(Camera::centered(vec2(0.0f, 0.0f), 1.0f, 1, 1)) {
  program_ = std::make_unique<ShaderProgram>("primitives", primitive_vertex_shader,
                                             primitive_fragment_shader);
  world_to_clip_location_ = program_->uniform_location("u_world_to_clip");
  viewport_location_ = program_->uniform_location("u_viewport");

  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &instance_buffer_);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
  const GLsizei stride = sizeof(Instance);
  const auto attribute = [stride](GLuint location, GLint size, GLenum type, std::size_t offset) {
    glEnableVertexAttribArray(location);
    const void* pointer = reinterpret_cast<const void*>(offset);
    if (type == GL_UNSIGNED_INT) {
      glVertexAttribIPointer(location, size, type, stride, pointer);
    } else {
      glVertexAttribPointer(location, size, type, type == GL_UNSIGNED_BYTE ? GL_TRUE : GL_FALSE,
                            stride, pointer);
    }
    glVertexAttribDivisor(location, 1);  // one value per instance
  };
  attribute(0, 2, GL_FLOAT, offsetof(Instance, p0));
  attribute(1, 2, GL_FLOAT, offsetof(Instance, p1));
  attribute(2, 2, GL_FLOAT, offsetof(Instance, p2));
  attribute(3, 2, GL_FLOAT, offsetof(Instance, params));
  attribute(4, 4, GL_UNSIGNED_BYTE, offsetof(Instance, color));
  attribute(5, 1, GL_UNSIGNED_INT, offsetof(Instance, kind));
  glBindVertexArray(0);
}

PrimitiveRenderer::~PrimitiveRenderer() {
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

void PrimitiveRenderer::begin(const Camera& camera) {
  camera_ = camera;
  instances_.clear();
}

void PrimitiveRenderer::finish(Color background) {
  glViewport(0, 0, camera_.width(), camera_.height());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!instances_.empty()) {
    glEnable(GL_BLEND);
    // Colour: straight-alpha "over"; alpha: stays at the cleared 1.0, so frames are opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program_->use();
    glUniformMatrix4fv(world_to_clip_location_, 1, GL_FALSE, glm::value_ptr(camera_.world_to_clip()));
    glUniform2f(viewport_location_, static_cast<float>(camera_.width()),
                static_cast<float>(camera_.height()));
    glBindVertexArray(vertex_array_);
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(instances_.size() * sizeof(Instance)),
                 instances_.data(), GL_STREAM_DRAW);
    glDrawArraysInstanced(GL_TRIANGLES, 0, 6, static_cast<GLsizei>(instances_.size()));
    glBindVertexArray(0);
  }
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw RenderError("PrimitiveRenderer::finish: OpenGL error " + hex(error) + " while drawing " +
                      std::to_string(instances_.size()) + " primitives");
  }
}

void PrimitiveRenderer::push(PrimitiveKindValue kind, vec2 p0, vec2 p1, vec2 p2, vec2 params,
                             Color color) {
  instances_.push_back(Instance{{p0.x, p0.y},
                                {p1.x, p1.y},
                                {p2.x, p2.y},
                                {params.x, params.y},
                                {to_byte(color.r), to_byte(color.g), to_byte(color.b), to_byte(color.a)},
                                kind});
}

void PrimitiveRenderer::push_segment(vec2 from, vec2 to, float extension_pixels, Color color) {
  push(kind_value(PrimitiveKind::Segment), from, to, vec2(0.0f),
       vec2(0.5f * style_.line_width, extension_pixels), color);
}

void PrimitiveRenderer::draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) {
  if (count < 3) return;
  if (count == 4 && is_parallelogram(vertices)) {
    push(kind_value(PrimitiveKind::Parallelogram), vertices[0], vertices[1], vertices[2], vec2(0.0f), fill);
  } else {
    for (int i = 1; i + 1 < count; ++i) {
      push(kind_value(PrimitiveKind::Triangle), vertices[0], vertices[i], vertices[i + 1], vec2(0.0f), fill);
    }
  }
  // Square ends half a line wide, so neighbouring edges meet without a notch at corners.
  for (int i = 0; i < count; ++i) {
    push_segment(vertices[i], vertices[(i + 1) % count], 0.5f * style_.line_width, outline);
  }
}

void PrimitiveRenderer::draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) {
  const float radius_pixels = radius * camera_.pixels_per_metre();
  const float half_width = 0.5f * style_.line_width;
  push(kind_value(PrimitiveKind::Disc), center, vec2(0.0f), vec2(0.0f), vec2(radius_pixels, 0.0f), fill);
  push(kind_value(PrimitiveKind::Disc), center, vec2(0.0f), vec2(0.0f),
       vec2(radius_pixels + half_width, style_.line_width), outline);
  push_segment(center, center + axis * radius, 0.0f, outline);
}

void PrimitiveRenderer::draw_segment(vec2 from, vec2 to, Color color) {
  push_segment(from, to, 0.5f * style_.line_width, color);
}

void PrimitiveRenderer::draw_arrow(vec2 from, vec2 to, Color color) {
  const float pixels_per_metre = camera_.pixels_per_metre();
  const float length_pixels = std::sqrt(length_squared(to - from)) * pixels_per_metre;
  if (!(length_pixels > 1e-3f)) return;  // nothing to point along (also rejects NaN)
  const vec2 direction = (to - from) * (pixels_per_metre / length_pixels);
  // Short arrows get a proportionally smaller head, at most half their length.
  const float head_length_pixels = std::min(style_.arrow_head_length, 0.5f * length_pixels);
  const float head_half_width_pixels =
      0.5f * style_.arrow_head_width * head_length_pixels / style_.arrow_head_length;
  const vec2 base = to - direction * (head_length_pixels / pixels_per_metre);
  const vec2 side = left_perpendicular(direction) * (head_half_width_pixels / pixels_per_metre);
  push_segment(from, base, 0.0f, color);
  push(kind_value(PrimitiveKind::Triangle), to, base + side, base - side, vec2(0.0f), color);
}

void PrimitiveRenderer::draw_point(vec2 position, float size_pixels, Color color) {
  push(kind_value(PrimitiveKind::Disc), position, vec2(0.0f), vec2(0.0f), vec2(0.5f * size_pixels, 0.0f), color);
}

void PrimitiveRenderer::draw_text(vec2 position, const std::string& text, Color color) {
  glyphs_.clear();
  layout_text(text, glyphs_);
  const float scale = static_cast<float>(style_.label_scale);
  for (const GlyphRect& glyph : glyphs_) {
    // Font y grows downwards from the top of the line; the anchor is the baseline, y up.
    push(kind_value(PrimitiveKind::AnchoredRect), position,
         vec2(glyph.left, font_cap_height - glyph.bottom) * scale,
         vec2(glyph.right, font_cap_height - glyph.top) * scale, vec2(0.0f), color);
  }
}

void PrimitiveRenderer::draw_screen_rect(vec2 top_left, vec2 size, Color color) {
  const float height = static_cast<float>(camera_.height());
  push(kind_value(PrimitiveKind::ScreenRect), vec2(0.0f), vec2(top_left.x, height - (top_left.y + size.y)),
       vec2(top_left.x + size.x, height - top_left.y), vec2(0.0f), color);
}

void PrimitiveRenderer::draw_screen_text(vec2 top_left, const std::string& text, Color color, int scale) {
  glyphs_.clear();
  layout_text(text, glyphs_);
  const float s = static_cast<float>(scale);
  for (const GlyphRect& glyph : glyphs_) {
    draw_screen_rect(top_left + vec2(glyph.left, glyph.top) * s,
                     vec2(glyph.right - glyph.left, glyph.bottom - glyph.top) * s, color);
  }
}

}  // namespace impulse2d::render

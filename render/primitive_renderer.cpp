/// @file primitive_renderer.cpp
#include "render/primitive_renderer.h"

#include "render/gl_api.h"
#include "render/primitive_shaders.h"
#include "render/render_error.h"
#include "render/shader_program.h"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace impulse2d::render {

namespace {

// Extent of solid primitives: so large that the rectangle coverage is 1 everywhere.
constexpr float kSolidExtent = 1.0e6f;

std::uint8_t to_byte(float channel) {
  const float clamped = std::min(std::max(channel, 0.0f), 1.0f);
  return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
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
  viewport_location_ = program_->uniform_location("u_viewport");

  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &vertex_buffer_);
  glGenBuffers(1, &index_buffer_);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);  // recorded in the vertex array
  const GLsizei stride = sizeof(Vertex);
  const auto attribute = [stride](GLuint location, GLint size, GLenum type, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, type, type == GL_UNSIGNED_BYTE ? GL_TRUE : GL_FALSE, stride,
                          reinterpret_cast<const void*>(offset));
  };
  attribute(0, 2, GL_FLOAT, offsetof(Vertex, position));
  attribute(1, 2, GL_FLOAT, offsetof(Vertex, local));
  attribute(2, 2, GL_FLOAT, offsetof(Vertex, extent));
  attribute(3, 4, GL_UNSIGNED_BYTE, offsetof(Vertex, color));
  glBindVertexArray(0);
}

PrimitiveRenderer::~PrimitiveRenderer() {
  glDeleteBuffers(1, &index_buffer_);
  glDeleteBuffers(1, &vertex_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
}

void PrimitiveRenderer::begin(const Camera& camera) {
  camera_ = camera;
  // The camera's orthographic matrix, then clip space to window pixels (origin bottom-left).
  const glm::mat4 clip = camera.world_to_clip();
  const float half_width = 0.5f * static_cast<float>(camera.width());
  const float half_height = 0.5f * static_cast<float>(camera.height());
  world_to_window_[0] = clip[0][0] * half_width;
  world_to_window_[1] = (clip[3][0] + 1.0f) * half_width;
  world_to_window_[2] = clip[1][1] * half_height;
  world_to_window_[3] = (clip[3][1] + 1.0f) * half_height;
  vertices_.clear();
}

vec2 PrimitiveRenderer::to_window(vec2 world) const {
  return vec2(world.x * world_to_window_[0] + world_to_window_[1], world.y * world_to_window_[2] + world_to_window_[3]);
}

void PrimitiveRenderer::finish(Color background) {
  glViewport(0, 0, camera_.width(), camera_.height());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  const std::size_t quads = primitive_count();
  if (quads > 0) {
    glBindVertexArray(vertex_array_);
    if (quads > capacity_quads_) {
      // Buffers grow geometrically and are kept for later frames: reallocating them every
      // frame costs more in page faults than the upload itself.
      capacity_quads_ = std::max(quads, 2 * capacity_quads_);
      glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity_quads_ * 4 * sizeof(Vertex)), nullptr,
                   GL_STREAM_DRAW);
      // Two triangles per quad.
      std::vector<GLuint> indices(capacity_quads_ * 6);
      for (std::size_t q = 0; q < capacity_quads_; ++q) {
        const GLuint first = static_cast<GLuint>(4 * q);
        const GLuint quad[6] = {first, first + 1, first + 2, first, first + 2, first + 3};
        std::copy(quad, quad + 6, indices.begin() + static_cast<std::ptrdiff_t>(6 * q));
      }
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
                   indices.data(), GL_STATIC_DRAW);
    }
    glEnable(GL_BLEND);
    // Colour: straight-alpha "over"; alpha: stays at the cleared 1.0, so frames are opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    program_->use();
    glUniform2f(viewport_location_, static_cast<float>(camera_.width()), static_cast<float>(camera_.height()));
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(vertices_.size() * sizeof(Vertex)), vertices_.data());
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(quads * 6), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
  }
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw RenderError("PrimitiveRenderer::finish: OpenGL error " + hex(error) + " while drawing " +
                      std::to_string(quads) + " primitives");
  }
}

void PrimitiveRenderer::push_solid(vec2 a, vec2 b, vec2 c, vec2 d, Color color) {
  const std::uint8_t rgba[4] = {to_byte(color.r), to_byte(color.g), to_byte(color.b), to_byte(color.a)};
  for (const vec2 corner : {a, b, c, d}) {
    vertices_.push_back(Vertex{{corner.x, corner.y}, {0.0f, 0.0f}, {kSolidExtent, kSolidExtent},
                               {rgba[0], rgba[1], rgba[2], rgba[3]}});
  }
}

void PrimitiveRenderer::push_segment(vec2 from, vec2 to, float extension_pixels, Color color) {
  const vec2 a = to_window(from);
  const vec2 b = to_window(to);
  const float length = std::sqrt(length_squared(b - a));
  const vec2 direction = length > 1e-6f ? (b - a) / length : vec2(1.0f, 0.0f);
  const vec2 normal = left_perpendicular(direction);
  const vec2 extent(0.5f * length + extension_pixels, 0.5f * style_.line_width);
  const vec2 reach = extent + 1.0f;  // one pixel of room for the anti-aliased edge
  const vec2 middle = 0.5f * (a + b);
  const std::uint8_t rgba[4] = {to_byte(color.r), to_byte(color.g), to_byte(color.b), to_byte(color.a)};
  for (const vec2 side : {vec2(-1.0f, -1.0f), vec2(1.0f, -1.0f), vec2(1.0f, 1.0f), vec2(-1.0f, 1.0f)}) {
    const vec2 local = side * reach;
    const vec2 corner = middle + direction * local.x + normal * local.y;
    vertices_.push_back(Vertex{{corner.x, corner.y}, {local.x, local.y}, {extent.x, extent.y},
                               {rgba[0], rgba[1], rgba[2], rgba[3]}});
  }
}

void PrimitiveRenderer::push_disc(vec2 center, float radius_pixels, float ring_width_pixels, Color color) {
  if (!(radius_pixels > 0.0f)) return;
  const vec2 c = to_window(center);
  const float reach = radius_pixels + 1.0f;
  const std::uint8_t rgba[4] = {to_byte(color.r), to_byte(color.g), to_byte(color.b), to_byte(color.a)};
  for (const vec2 side : {vec2(-1.0f, -1.0f), vec2(1.0f, -1.0f), vec2(1.0f, 1.0f), vec2(-1.0f, 1.0f)}) {
    const vec2 local = side * reach;
    vertices_.push_back(Vertex{{c.x + local.x, c.y + local.y}, {local.x, local.y},
                               {-radius_pixels, ring_width_pixels}, {rgba[0], rgba[1], rgba[2], rgba[3]}});
  }
}

void PrimitiveRenderer::push_text(vec2 window_top_left, const std::string& text, Color color, float scale) {
  glyphs_.clear();
  layout_text(text, glyphs_);
  for (const GlyphRect& glyph : glyphs_) {
    const float left = window_top_left.x + glyph.left * scale;
    const float right = window_top_left.x + glyph.right * scale;
    const float top = window_top_left.y - glyph.top * scale;  // window y grows upwards
    const float bottom = window_top_left.y - glyph.bottom * scale;
    push_solid(vec2(left, bottom), vec2(right, bottom), vec2(right, top), vec2(left, top), color);
  }
}

void PrimitiveRenderer::draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) {
  if (count < 3) return;
  const vec2 first = to_window(vertices[0]);
  for (int i = 1; i + 1 < count; i += 2) {
    // Fan quads (first, i, i+1, i+2), the last one a triangle when the count runs out.
    const vec2 b = to_window(vertices[i]);
    const vec2 c = to_window(vertices[i + 1]);
    const vec2 d = i + 2 < count ? to_window(vertices[i + 2]) : c;
    push_solid(first, b, c, d, fill);
  }
  // Square ends half a line wide, so neighbouring edges meet without a notch at corners.
  for (int i = 0; i < count; ++i) {
    push_segment(vertices[i], vertices[(i + 1) % count], 0.5f * style_.line_width, outline);
  }
}

void PrimitiveRenderer::draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) {
  const float radius_pixels = radius * camera_.pixels_per_metre();
  push_disc(center, radius_pixels, 0.0f, fill);
  push_disc(center, radius_pixels + 0.5f * style_.line_width, style_.line_width, outline);
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
  const float head_half_width_pixels = 0.5f * style_.arrow_head_width * head_length_pixels / style_.arrow_head_length;
  const vec2 base = to - direction * (head_length_pixels / pixels_per_metre);
  push_segment(from, base, 0.0f, color);
  const vec2 tip = to_window(to);
  const vec2 window_base = to_window(base);
  const vec2 side = left_perpendicular(direction) * head_half_width_pixels;  // y up in both spaces
  push_solid(tip, window_base + side, window_base - side, window_base - side, color);
}

void PrimitiveRenderer::draw_point(vec2 position, float size_pixels, Color color) {
  push_disc(position, 0.5f * size_pixels, 0.0f, color);
}

void PrimitiveRenderer::draw_text(vec2 position, const std::string& text, Color color) {
  // The anchor is the baseline's left end, snapped to a pixel corner so glyphs stay crisp.
  const vec2 anchor = to_window(position);
  const float scale = static_cast<float>(style_.label_scale);
  push_text(vec2(std::floor(anchor.x + 0.5f), std::floor(anchor.y + 0.5f) + font_cap_height * scale), text, color,
            scale);
}

void PrimitiveRenderer::draw_screen_rect(vec2 top_left, vec2 size, Color color) {
  const float height = static_cast<float>(camera_.height());
  const float left = top_left.x;
  const float right = top_left.x + size.x;
  const float top = height - top_left.y;
  const float bottom = height - (top_left.y + size.y);
  push_solid(vec2(left, bottom), vec2(right, bottom), vec2(right, top), vec2(left, top), color);
}

void PrimitiveRenderer::draw_screen_text(vec2 top_left, const std::string& text, Color color, int scale) {
  push_text(vec2(top_left.x, static_cast<float>(camera_.height()) - top_left.y), text, color,
            static_cast<float>(scale));
}

}  // namespace impulse2d::render

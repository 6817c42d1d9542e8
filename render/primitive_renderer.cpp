/// @file primitive_renderer.cpp
#include "render/primitive_renderer.h"

#include "render/easy_font.h"
#include "render/gl_api.h"
#include "render/primitive_shaders.h"
#include "render/render_error.h"
#include "render/shader_program.h"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>
#include <limits>
#include <type_traits>
#include <vector>

namespace impulse2d::render {

namespace {

// Pixels around a primitive's edge that its sprite or quad covers: anti-aliased coverage
// reaches half a pixel beyond every edge and is 0 from there on (an arrow head's mitred
// base corners reach further; draw_arrow widens its bounds for them).
constexpr float kMargin = 0.5f;
// Sprites up to this many pixels across are always points. Larger ones are points only
// while their square is at most kMaxSpriteWaste times the primitive's own rectangle
// (kRunSpriteWaste right after a point sprite of the same kind, so that fewer switches
// between sprites and quads split the kind's run into more draw calls); otherwise (a long
// or diagonal line) a quad hugs the primitive. llvmpipe's cost follows the 4x4 pixel blocks
// a primitive touches more than the primitive count. Chosen by instruction counts
// (callgrind, LP_NUM_THREADS=0, steady state) of the 1000-body every-overlay frame of
// bench_render with one program per kind: 8, 4 and 5.5 gave 207 M a frame (37 M shapes
// only; 188 draw calls instead of 822); 8, 4 and no run limit, 210 M (41 M); 8, 4 and 8,
// 214 M (37 M); 6 and 2.5, 214 M; 12 and 8, 214 M. With one program for every kind, 6
// and 2.5 had been best (docs/rendering.md).
constexpr float kSmallSprite = 8.0f;
constexpr float kMaxSpriteWaste = 4.0f;
constexpr float kRunSpriteWaste = 5.5f;

void set_color(std::uint8_t (&rgba)[4], Color color) {
  for (int i = 0; i < 4; ++i) {
    const float channel = i == 0 ? color.r : i == 1 ? color.g : i == 2 ? color.b : color.a;
    const float scaled = std::min(std::max(channel, 0.0f), 1.0f) * 255.0f;
    // std::lround without the library call (a tenth of the batch building): x + 0.5 is exact
    // in double, so truncating it rounds halves away from zero; NaN gives 0, as before.
    rgba[i] = scaled >= 0.0f ? static_cast<std::uint8_t>(static_cast<double>(scaled) + 0.5) : 0;
  }
}

std::string hex(unsigned value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%04X", value);
  return text;
}

}  // namespace

PrimitiveRenderer::PrimitiveRenderer(const PrimitiveStyle& style)
    : style_(style),
      camera_(Camera::centered(vec2(0.0f, 0.0f), 1.0f, 1, 1)),
      software_raster_(raster_thread_count()) {
  for (int kind = 0; kind < primitive_kind_count; ++kind) {
    const std::string fragment_shader = primitive_fragment_shader(static_cast<PrimitiveKind>(kind));
    programs_[kind] = std::make_unique<ShaderProgram>(
        "primitives " + std::to_string(kind), primitive_vertex_shader(static_cast<PrimitiveKind>(kind)),
        fragment_shader.c_str());
    viewport_locations_[kind] = programs_[kind]->uniform_location("u_viewport");
  }
  GLfloat point_sizes[2] = {1.0f, 1.0f};
  glGetFloatv(GL_POINT_SIZE_RANGE, point_sizes);
  max_point_size_ = std::min(point_sizes[1], style_.max_point_sprite);

  glGenVertexArrays(3, vertex_arrays_);
  glGenBuffers(3, vertex_buffers_);
  glGenBuffers(1, &index_buffer_);
  const auto attribute = [](GLuint location, GLint size, GLenum type, GLsizei stride, std::size_t offset) {
    glEnableVertexAttribArray(location);
    const void* pointer = reinterpret_cast<const void*>(offset);
    if (type == GL_UNSIGNED_INT) {
      glVertexAttribIPointer(location, size, type, stride, pointer);
    } else {
      glVertexAttribPointer(location, size, type, type == GL_UNSIGNED_BYTE ? GL_TRUE : GL_FALSE, stride, pointer);
    }
  };
  glBindVertexArray(vertex_arrays_[0]);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[0]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  const GLsizei polygon_stride = sizeof(PolygonVertex);
  attribute(0, 3, GL_FLOAT, polygon_stride, offsetof(PolygonVertex, sprite));
  attribute(1, 3, GL_FLOAT, polygon_stride, offsetof(PolygonVertex, origin));
  attribute(2, 4, GL_UNSIGNED_BYTE, polygon_stride, offsetof(PolygonVertex, fill));
  attribute(3, 4, GL_UNSIGNED_BYTE, polygon_stride, offsetof(PolygonVertex, line));
  for (int edge = 0; edge < polygon_primitive_edges; ++edge) {
    attribute(static_cast<GLuint>(4 + edge), 3, GL_FLOAT, polygon_stride,
              offsetof(PolygonVertex, edges) + sizeof(PolygonVertex::edges[0]) * static_cast<std::size_t>(edge));
  }
  glBindVertexArray(vertex_arrays_[1]);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[1]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  const GLsizei stride = sizeof(ShapeVertex);
  attribute(0, 3, GL_FLOAT, stride, offsetof(ShapeVertex, sprite));
  attribute(1, 4, GL_FLOAT, stride, offsetof(ShapeVertex, frame));
  attribute(2, 4, GL_FLOAT, stride, offsetof(ShapeVertex, box));
  attribute(3, 4, GL_FLOAT, stride, offsetof(ShapeVertex, head));
  attribute(4, 3, GL_FLOAT, stride, offsetof(ShapeVertex, disc));
  attribute(5, 4, GL_UNSIGNED_BYTE, stride, offsetof(ShapeVertex, fill));
  attribute(6, 4, GL_UNSIGNED_BYTE, stride, offsetof(ShapeVertex, line));
  glBindVertexArray(vertex_arrays_[2]);
  glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[2]);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);
  const GLsizei text_stride = sizeof(TextVertex);
  attribute(0, 3, GL_FLOAT, text_stride, offsetof(TextVertex, sprite));
  attribute(1, 4, GL_FLOAT, text_stride, offsetof(TextVertex, run));
  attribute(2, 1, GL_FLOAT, text_stride, offsetof(TextVertex, font_scale));
  attribute(3, 4, GL_UNSIGNED_BYTE, text_stride, offsetof(TextVertex, fill));
  attribute(4, 4, GL_UNSIGNED_INT, text_stride, offsetof(TextVertex, bits));
  attribute(5, 4, GL_UNSIGNED_INT, text_stride, offsetof(TextVertex, bits) + 4 * sizeof(std::uint32_t));
  glBindVertexArray(0);
}

PrimitiveRenderer::~PrimitiveRenderer() {
  glDeleteBuffers(1, &index_buffer_);
  glDeleteBuffers(3, vertex_buffers_);
  glDeleteVertexArrays(3, vertex_arrays_);
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
  polygons_.vertices.clear();
  polygons_.open_runs.clear();
  for (Batch<ShapeVertex>& kind_batch : batches_) {
    kind_batch.vertices.clear();
    kind_batch.open_runs.clear();
  }
  texts_.vertices.clear();
  texts_.open_runs.clear();
  runs_.clear();
  software_layers_ = false;
  software_.clear();
  for (std::vector<SoftwarePrimitive>& open : software_open_) open.clear();
  primitive_count_ = 0;
}

void PrimitiveRenderer::start_software_layers() { software_layers_ = true; }

void PrimitiveRenderer::next_layer() {
  runs_.insert(runs_.end(), polygons_.open_runs.begin(), polygons_.open_runs.end());
  polygons_.open_runs.clear();
  for (Batch<ShapeVertex>& kind_batch : batches_) {
    runs_.insert(runs_.end(), kind_batch.open_runs.begin(), kind_batch.open_runs.end());
    kind_batch.open_runs.clear();
  }
  runs_.insert(runs_.end(), texts_.open_runs.begin(), texts_.open_runs.end());
  texts_.open_runs.clear();
  for (std::vector<SoftwarePrimitive>& open : software_open_) {
    software_.primitives.insert(software_.primitives.end(), open.begin(), open.end());
    open.clear();
  }
}

void PrimitiveRenderer::draw_software_layers(Frame& frame) {
  if (frame.width != camera_.width() || frame.height != camera_.height()) {
    throw RenderError("PrimitiveRenderer::draw_software_layers: the frame is " + std::to_string(frame.width) + "x" +
                      std::to_string(frame.height) + " but the camera's " + std::to_string(camera_.width()) + "x" +
                      std::to_string(camera_.height()));
  }
  software_raster_.draw(software_, frame);
}

template <typename V>
std::uint32_t PrimitiveRenderer::add_software_parameters(const V& shape) {
  std::vector<V>* list = nullptr;
  if constexpr (std::is_same_v<V, ShapeVertex>) {
    list = &software_.shapes;
  } else if constexpr (std::is_same_v<V, PolygonVertex>) {
    list = &software_.polygons;
  } else if constexpr (std::is_same_v<V, TextVertex>) {
    list = &software_.texts;
  } else {
    static_assert(std::is_same_v<V, FillQuad>, "a kind of CPU primitive parameters");
    list = &software_.fill_quads;
  }
  list->push_back(shape);
  return static_cast<std::uint32_t>(list->size() - 1);
}

namespace {

// The pixels [first, last] of a row (or column) `size` pixels long whose centres (i + 0.5) lie
// in [low, high]; first > last when there are none or a bound is NaN. The bounds are first
// brought within a pixel of the row, where an integer conversion rounds them exactly (the
// ceiling and floor of the rounded values, without a libm call).
void pixel_span(float low, float high, int size, int& first, int& last) {
  first = 0;
  last = -1;
  if (!(low <= high)) return;
  const float end = static_cast<float>(size);
  const float from = std::min(std::max(low - 0.5f, -1.0f), end);
  const float to = std::min(std::max(high - 0.5f, -1.0f), end);
  int ceiling = static_cast<int>(from);  // truncation: the ceiling for negative values, else below it
  if (static_cast<float>(ceiling) < from) ++ceiling;
  int floor = static_cast<int>(to);  // the floor for non-negative values, else above it
  if (static_cast<float>(floor) > to) --floor;
  first = std::max(ceiling, 0);
  last = std::min(floor, size - 1);
}

}  // namespace

template <typename V>
SoftwarePrimitive* PrimitiveRenderer::push_software(PrimitiveKind kind, const V& shape, vec2 lower, vec2 upper) {
  // The pixels whose centres (column + 0.5, row + 0.5) lie in [lower, upper], inside the frame.
  SoftwarePrimitive primitive;
  pixel_span(lower.x, upper.x, camera_.width(), primitive.left, primitive.right);
  if (primitive.left > primitive.right) return nullptr;
  pixel_span(lower.y, upper.y, camera_.height(), primitive.bottom, primitive.top);
  if (primitive.bottom > primitive.top) return nullptr;
  primitive.kind = kind;
  primitive.index = add_software_parameters(shape);
  return &software_open_[static_cast<int>(kind)].emplace_back(primitive);
}

vec2 PrimitiveRenderer::to_window(vec2 world) const {
  return vec2(world.x * world_to_window_[0] + world_to_window_[1], world.y * world_to_window_[2] + world_to_window_[3]);
}

namespace {

// Makes `buffer` (bound to GL_ARRAY_BUFFER) hold at least `count` vertices of `size` bytes.
void reserve_vertices(std::size_t count, std::size_t size, std::size_t& capacity) {
  if (count <= capacity) return;
  // Buffers grow geometrically and are kept for later frames: reallocating them every frame
  // costs more in page faults than the upload itself.
  capacity = std::max(count, 2 * capacity);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(capacity * size), nullptr, GL_STREAM_DRAW);
}

template <typename V>
void upload(const std::vector<V>& vertices, std::size_t first) {
  if (vertices.empty()) return;
  glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(first * sizeof(V)),
                  static_cast<GLsizeiptr>(vertices.size() * sizeof(V)), vertices.data());
}

}  // namespace

void PrimitiveRenderer::finish(Color background) {
  next_layer();
  glViewport(0, 0, camera_.width(), camera_.height());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(background.r, background.g, background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!runs_.empty()) {
    // The polygons' and the text's vertices go to buffers of their own; each other kind's to
    // its own stretch of the second.
    std::size_t first_of_kind[primitive_kind_count] = {};
    std::size_t shape_vertices = 0;
    for (int kind = 1; kind < primitive_kind_count - 1; ++kind) {
      first_of_kind[kind] = shape_vertices;
      shape_vertices += batches_[kind - 1].vertices.size();
    }
    std::size_t most_quads = 0;
    for (const Run& run : runs_) {
      if (!run.points) most_quads = std::max(most_quads, run.vertices / 4);
    }
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[0]);
    reserve_vertices(polygons_.vertices.size(), sizeof(PolygonVertex), capacity_vertices_[0]);
    upload(polygons_.vertices, 0);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[1]);
    reserve_vertices(shape_vertices, sizeof(ShapeVertex), capacity_vertices_[1]);
    for (int kind = 1; kind < primitive_kind_count - 1; ++kind) upload(batches_[kind - 1].vertices, first_of_kind[kind]);
    glBindBuffer(GL_ARRAY_BUFFER, vertex_buffers_[2]);
    reserve_vertices(texts_.vertices.size(), sizeof(TextVertex), capacity_vertices_[2]);
    upload(texts_.vertices, 0);
    if (most_quads > capacity_quads_) {
      // Two triangles (0, 1, 2) and (0, 2, 3) per quad; a run starts at its base vertex.
      capacity_quads_ = std::max(most_quads, 2 * capacity_quads_);
      std::vector<GLuint> indices(6 * capacity_quads_);
      for (std::size_t quad = 0; quad < capacity_quads_; ++quad) {
        const auto corner = static_cast<GLuint>(4 * quad);
        const GLuint pattern[6] = {corner, corner + 1, corner + 2, corner, corner + 2, corner + 3};
        std::copy(pattern, pattern + 6, indices.begin() + static_cast<std::ptrdiff_t>(6 * quad));
      }
      glBindVertexArray(vertex_arrays_[0]);
      glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(GLuint)),
                   indices.data(), GL_STATIC_DRAW);
    }
    glEnable(GL_BLEND);
    // Premultiplied "over" (the fragment stage multiplies coverage and alpha into the
    // colour); alpha stays at the cleared 1.0, so frames are opaque.
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_PROGRAM_POINT_SIZE);
    int current_kind = -1;
    for (const Run& run : runs_) {
      const int kind = static_cast<int>(run.kind);
      if (kind != current_kind) {
        programs_[kind]->use();
        glUniform2f(viewport_locations_[kind], static_cast<float>(camera_.width()),
                    static_cast<float>(camera_.height()));
        glBindVertexArray(vertex_arrays_[run.kind == PrimitiveKind::polygon ? 0 : run.kind == PrimitiveKind::text ? 2 : 1]);
        current_kind = kind;
      }
      const auto first = static_cast<GLint>(first_of_kind[kind] + run.first_vertex);
      if (run.points) {
        glDrawArrays(GL_POINTS, first, static_cast<GLsizei>(run.vertices));
      } else {
        glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(run.vertices / 4 * 6), GL_UNSIGNED_INT, nullptr,
                                 first);
      }
    }
    glBindVertexArray(0);
  }
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw RenderError("PrimitiveRenderer::finish: OpenGL error " + hex(error) + " while drawing " +
                      std::to_string(primitive_count_) + " primitives");
  }
}

template <typename V>
void PrimitiveRenderer::push_vertex(Batch<V>& kind_batch, PrimitiveKind kind, const V& shape, vec2 position,
                                    float point_size, bool point) {
  if (kind_batch.open_runs.empty() || kind_batch.open_runs.back().points != point) {
    kind_batch.open_runs.push_back(Run{kind, point, kind_batch.vertices.size(), 0});
  }
  ++kind_batch.open_runs.back().vertices;
  V& vertex = kind_batch.vertices.emplace_back(shape);
  vertex.sprite[0] = position.x;
  vertex.sprite[1] = position.y;
  vertex.sprite[2] = point_size;
}

void PrimitiveRenderer::push_quad(PrimitiveKind kind, const ShapeVertex& shape, const vec2 (&corners)[4]) {
  for (const vec2 corner : corners) push_vertex(batch(kind), kind, shape, corner, 1.0f, false);
}

template <typename V>
void PrimitiveRenderer::push_bounded(Batch<V>& kind_batch, PrimitiveKind kind, const V& shape, vec2 lower, vec2 upper,
                                     float area) {
  ++primitive_count_;
  if (software_layers_) {
    push_software(kind, shape, lower, upper);
    return;
  }
  const bool after_point = !kind_batch.open_runs.empty() && kind_batch.open_runs.back().points;
  if (fits_point_sprite(lower, upper, area, after_point)) {
    push_vertex(kind_batch, kind, shape, 0.5f * (lower + upper), std::max(upper.x - lower.x, upper.y - lower.y), true);
  } else {
    const vec2 quad[4] = {lower, vec2(upper.x, lower.y), upper, vec2(lower.x, upper.y)};
    for (const vec2 corner : quad) push_vertex(kind_batch, kind, shape, corner, 1.0f, false);
  }
}

bool PrimitiveRenderer::fits_point_sprite(vec2 lower, vec2 upper, float area, bool after_point) const {
  const float side = std::max(upper.x - lower.x, upper.y - lower.y);
  const vec2 center = 0.5f * (lower + upper);
  // GL drops a whole point whose centre lies outside the viewport, so those are quads.
  const bool centre_visible = center.x >= 0.0f && center.y >= 0.0f && center.x <= static_cast<float>(camera_.width()) &&
                              center.y <= static_cast<float>(camera_.height());
  // After a point sprite of the same kind a looser limit keeps the run going: every switch
  // between sprites and quads is another draw call.
  const float waste = after_point ? kRunSpriteWaste : kMaxSpriteWaste;
  return centre_visible && side <= max_point_size_ && (side <= kSmallSprite || side * side <= waste * area);
}

void PrimitiveRenderer::push_shape(PrimitiveKind kind, const ShapeVertex& shape, vec2 lower, vec2 upper) {
  // The rectangle [lower, upper] of the primitive's frame, grown by the margin, in window pixels.
  const vec2 origin(shape.frame[0], shape.frame[1]);
  const vec2 axis(shape.frame[2], shape.frame[3]);
  const vec2 normal = left_perpendicular(axis);
  const vec2 low = lower - kMargin;
  const vec2 high = upper + kMargin;
  const vec2 corners[4] = {origin + axis * low.x + normal * low.y, origin + axis * high.x + normal * low.y,
                           origin + axis * high.x + normal * high.y, origin + axis * low.x + normal * high.y};
  vec2 box_lower = corners[0];
  vec2 box_upper = corners[0];
  for (const vec2 corner : corners) {
    box_lower = glm::min(box_lower, corner);
    box_upper = glm::max(box_upper, corner);
  }
  ++primitive_count_;
  if (software_layers_) {
    if (SoftwarePrimitive* primitive = push_software(kind, shape, box_lower, box_upper)) {
      primitive->frame_lower = low;
      primitive->frame_upper = high;
    }
    return;
  }
  const std::vector<Run>& runs = batch(kind).open_runs;
  if (fits_point_sprite(box_lower, box_upper, (high.x - low.x) * (high.y - low.y), !runs.empty() && runs.back().points)) {
    push_vertex(batch(kind), kind, shape, 0.5f * (box_lower + box_upper),
                std::max(box_upper.x - box_lower.x, box_upper.y - box_lower.y), true);
  } else {
    push_quad(kind, shape, corners);
  }
}

void PrimitiveRenderer::push_filled_triangles(const vec2* window_vertices, int count, Color fill) {
  // Fan quads (first, i, i+1, i+2), the last one a triangle when the count runs out.
  ShapeVertex solid;
  set_color(solid.fill, fill);
  const vec2 first = window_vertices[0];
  for (int i = 1; i + 1 < count; i += 2) {
    const vec2 d = i + 2 < count ? window_vertices[i + 2] : window_vertices[i + 1];  // else an empty triangle
    ++primitive_count_;
    if (software_layers_) {
      FillQuad quad{{first, window_vertices[i], window_vertices[i + 1], d}};
      std::copy(std::begin(solid.fill), std::end(solid.fill), quad.fill);
      push_software(PrimitiveKind::solid, quad, glm::min(glm::min(first, window_vertices[i]), glm::min(window_vertices[i + 1], d)),
                    glm::max(glm::max(first, window_vertices[i]), glm::max(window_vertices[i + 1], d)));
      continue;
    }
    push_quad(PrimitiveKind::solid, solid, {first, window_vertices[i], window_vertices[i + 1], d});
  }
}

void PrimitiveRenderer::push_segment(vec2 from, vec2 to, float extension_pixels, float width_pixels,
                                     Color color) {
  const vec2 a = to_window(from);
  const vec2 b = to_window(to);
  const float length = std::sqrt(length_squared(b - a));
  const vec2 direction = length > 1e-6f ? (b - a) / length : vec2(1.0f, 0.0f);
  const vec2 middle = 0.5f * (a + b);
  const vec2 half(0.5f * length + extension_pixels, 0.5f * width_pixels);
  ShapeVertex shape;
  shape.frame[0] = middle.x;
  shape.frame[1] = middle.y;
  shape.frame[2] = direction.x;
  shape.frame[3] = direction.y;
  shape.box[0] = half.x;
  shape.box[1] = half.y;
  set_color(shape.fill, color);
  push_shape(PrimitiveKind::box, shape, -half, half);
}

void PrimitiveRenderer::push_disc(vec2 center, float radius_pixels, Color fill, float ring_radius_pixels,
                                  Color ring) {
  const bool has_fill = radius_pixels > 0.0f;
  const bool has_ring = ring_radius_pixels > 0.0f;
  if (!has_fill && !has_ring) return;  // also rejects NaN
  const vec2 c = to_window(center);
  ShapeVertex shape;
  shape.frame[0] = c.x;
  shape.frame[1] = c.y;
  if (has_fill) {
    shape.disc[0] = radius_pixels;
    set_color(shape.fill, fill);
  }
  if (has_ring) {
    // A ring one line wide, centred on the radius `ring_radius_pixels`.
    shape.disc[1] = ring_radius_pixels + 0.5f * style_.line_width;
    shape.disc[2] = ring_radius_pixels - 0.5f * style_.line_width;
    set_color(shape.line, ring);
  }
  const float reach = std::max(radius_pixels, shape.disc[1]);
  push_shape(PrimitiveKind::disc, shape, vec2(-reach), vec2(reach));
}

void PrimitiveRenderer::push_box(vec2 middle, vec2 half, float outline_width, Color color) {
  ShapeVertex shape;
  shape.frame[0] = middle.x;
  shape.frame[1] = middle.y;
  shape.box[0] = half.x;
  shape.box[1] = half.y;
  shape.box[3] = outline_width;
  set_color(shape.fill, color);
  push_shape(PrimitiveKind::box, shape, -half, half);
}

void PrimitiveRenderer::push_rect(vec2 lower_left, vec2 upper_right, Color color) {
  push_box(0.5f * (upper_right + lower_left), 0.5f * (upper_right - lower_left), 0.0f, color);
}

void PrimitiveRenderer::push_text(vec2 window_top_left, const std::string& text, Color color, float scale) {
  // Runs of characters, each one primitive with the run's font pixels as a bitmap: a run
  // starts at an inked character and takes the next ones of its line while their ink fits
  // in `text_run_columns` font pixels. Characters never overlap (ink ends before the
  // advance), so a run's pixels are those of its characters drawn one by one.
  TextVertex run;
  set_color(run.fill, color);
  run.font_scale = 1.0f / scale;
  run.run[3] = static_cast<float>(font_glyph_rows) * scale;
  bool open = false;
  int column = 0;  // font pixels from the open run's left edge to the pen
  int ink_left = 0;
  int ink_top = 0;
  int ink_right = 0;
  int ink_bottom = 0;
  const auto close_run = [&] {
    if (!open) return;
    open = false;
    run.run[2] = static_cast<float>(ink_right) * scale;
    const vec2 lower(run.run[0] + static_cast<float>(ink_left) * scale - kMargin,
                     run.run[1] - static_cast<float>(ink_bottom) * scale - kMargin);
    const vec2 upper(run.run[0] + static_cast<float>(ink_right) * scale + kMargin,
                     run.run[1] - static_cast<float>(ink_top) * scale + kMargin);
    // Only a small run is a point sprite: a long one's square would be mostly empty (as an
    // area of 0 says).
    push_bounded(texts_, PrimitiveKind::text, run, lower, upper, 0.0f);
  };
  vec2 pen = window_top_left;
  for (const char character : text) {
    if (character == '\n') {
      close_run();
      pen = vec2(window_top_left.x, pen.y - font_line_height * scale);  // window y grows upwards
      continue;
    }
    const GlyphBitmap& glyph = glyph_bitmap(character);
    if (glyph.bits != 0) {
      if (open && column + glyph.ink_right > text_run_columns) close_run();
      if (!open) {
        open = true;
        column = 0;
        run.run[0] = pen.x;
        run.run[1] = pen.y;
        std::fill(std::begin(run.bits), std::end(run.bits), 0u);
        ink_left = glyph.ink_left;
        ink_top = glyph.ink_top;
        ink_bottom = glyph.ink_bottom;
      }
      for (int c = glyph.ink_left; c < glyph.ink_right; ++c) {
        const int bit = (column + c) * font_glyph_rows;
        const std::uint32_t rows = glyph.columns[c];
        run.bits[bit / 32] |= rows << (bit % 32);
        if (bit % 32 + font_glyph_rows > 32) run.bits[bit / 32 + 1] |= rows >> (32 - bit % 32);
      }
      ink_top = std::min(ink_top, glyph.ink_top);
      ink_bottom = std::max(ink_bottom, glyph.ink_bottom);
      ink_right = column + glyph.ink_right;
    }
    column += glyph.advance;
    pen.x += static_cast<float>(glyph.advance) * scale;
  }
  close_run();
}

void PrimitiveRenderer::draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) {
  if (count < 3) return;
  if (count > polygon_primitive_edges) {
    // The fill as the polygon's own triangles (coverage 1); the outline over its edges, with
    // square ends half a line wide so neighbouring edges meet without a notch at corners.
    std::vector<vec2> window_vertices(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) window_vertices[static_cast<std::size_t>(i)] = to_window(vertices[i]);
    push_filled_triangles(window_vertices.data(), count, fill);
    for (int i = 0; i < count; ++i) {
      push_segment(vertices[i], vertices[(i + 1) % count], 0.5f * style_.line_width, style_.line_width, outline);
    }
    return;
  }
  // One primitive: the pixel's distance to the polygon is the largest of its edges'.
  vec2 corners[polygon_primitive_edges];
  float twice_area = 0.0f;
  for (int i = 0; i < count; ++i) corners[i] = to_window(vertices[i]);
  for (int i = 0; i < count; ++i) twice_area += cross(corners[i], corners[(i + 1) % count]);
  const float outward = twice_area < 0.0f ? -1.0f : 1.0f;  // right of each edge when counter-clockwise
  const vec2 origin = corners[0];
  PolygonVertex shape;
  shape.origin[0] = origin.x;
  shape.origin[1] = origin.y;
  shape.origin[2] = 0.5f * style_.line_width;
  vec2 normals[polygon_primitive_edges];
  for (int i = 0; i < count; ++i) {
    const vec2 edge = corners[(i + 1) % count] - corners[i];
    const float length = std::sqrt(length_squared(edge));
    normals[i] = length > 1e-6f ? outward * right_perpendicular(edge) / length : vec2(0.0f);
    shape.edges[i][0] = normals[i].x;
    shape.edges[i][1] = normals[i].y;
    shape.edges[i][2] = length > 1e-6f ? dot(normals[i], corners[i] - origin) : 1.0e6f;
  }
  for (int i = count; i < polygon_primitive_edges; ++i) shape.edges[i][2] = 1.0e6f;
  set_color(shape.fill, fill);
  set_color(shape.line, outline);
  // Bounds: each corner's mitre point, where the outline's anti-aliased edge ends on both its
  // edges (corners sharper than about 30 degrees are cut short).
  const float reach = 0.5f * style_.line_width + kMargin;
  vec2 lower(std::numeric_limits<float>::max());
  vec2 upper(std::numeric_limits<float>::lowest());
  for (int i = 0; i < count; ++i) {
    const vec2 before = normals[(i + count - 1) % count];
    const vec2 after = normals[i];
    const vec2 far = corners[i] + reach * (before + after) / std::max(1.0f + dot(before, after), 0.125f);
    lower = glm::min(lower, far);
    upper = glm::max(upper, far);
  }
  push_bounded(polygons_, PrimitiveKind::polygon, shape, lower, upper, std::abs(0.5f * twice_area));
}

void PrimitiveRenderer::draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) {
  const float radius_pixels = radius * camera_.pixels_per_metre();
  push_disc(center, radius_pixels, fill, radius_pixels, outline);
  push_segment(center, center + axis * radius, 0.0f, style_.line_width, outline);
}

void PrimitiveRenderer::draw_segment(vec2 from, vec2 to, Color color) {
  push_segment(from, to, 0.5f * style_.line_width, style_.line_width, color);
}

void PrimitiveRenderer::draw_band(vec2 from, vec2 to, float width_pixels, Color color) {
  push_segment(from, to, 0.0f, width_pixels, color);
}

void PrimitiveRenderer::draw_box_outline(vec2 lower, vec2 upper, Color color) {
  const vec2 a = to_window(lower);
  const vec2 b = to_window(upper);
  // Half extents reach half a line beyond the edges; the rectangle one line further in is cut out.
  const vec2 half = 0.5f * glm::abs(b - a) + vec2(0.5f * style_.line_width);
  push_box(0.5f * (a + b), half, style_.line_width, color);
}

void PrimitiveRenderer::draw_arrow(vec2 from, vec2 to, Color color) {
  const vec2 tail = to_window(from);
  const vec2 tip = to_window(to);
  const float length = std::sqrt(length_squared(tip - tail));
  if (!(length > 1e-3f)) return;  // nothing to point along (also rejects NaN)
  const vec2 direction = (tip - tail) / length;
  // Short arrows get a proportionally smaller head, at most half their length.
  const float head_length = std::min(style_.arrow_head_length, 0.5f * length);
  const float head_half_width = 0.5f * style_.arrow_head_width * head_length / style_.arrow_head_length;
  const float half_line = 0.5f * style_.line_width;
  // The shaft runs on under the head until the head is as wide as the shaft, so the two
  // shapes overlap instead of meeting at an anti-aliased seam.
  const float under_head = head_half_width > half_line ? head_length * half_line / head_half_width : head_length;
  const float shaft_half = 0.5f * (length - std::min(head_length, under_head));
  // The frame's origin is the shaft's centre; the head's base and tip lie along +x.
  ShapeVertex shape;
  const vec2 middle = tail + direction * shaft_half;
  shape.frame[0] = middle.x;
  shape.frame[1] = middle.y;
  shape.frame[2] = direction.x;
  shape.frame[3] = direction.y;
  shape.box[0] = shaft_half;
  shape.box[1] = half_line;
  const float tip_x = length - shaft_half;
  const float side_length = std::sqrt(head_half_width * head_half_width + head_length * head_length);
  shape.head[0] = tip_x - head_length;
  shape.head[1] = tip_x;
  shape.head[2] = head_half_width / side_length;  // outward normal of the upper side
  shape.head[3] = head_length / side_length;
  set_color(shape.fill, color);
  // The head's anti-aliased edge is mitred: at the base corners it reaches
  // 0.5 (1 + normal.x) / normal.y pixels out from the head's side, more than the margin.
  const float head_reach = head_half_width + 0.5f * (1.0f + shape.head[2]) / shape.head[3] - kMargin;
  const float half_height = std::max(half_line, head_reach);
  push_shape(PrimitiveKind::arrow, shape, vec2(-shaft_half, -half_height), vec2(tip_x, half_height));
}

void PrimitiveRenderer::draw_point(vec2 position, float size_pixels, Color color) {
  push_disc(position, 0.5f * size_pixels * style_.point_scale, color, 0.0f, Color{});
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
  push_rect(vec2(top_left.x, height - (top_left.y + size.y)), vec2(top_left.x + size.x, height - top_left.y), color);
}

void PrimitiveRenderer::draw_screen_text(vec2 top_left, const std::string& text, Color color, int scale) {
  push_text(vec2(top_left.x, static_cast<float>(camera_.height()) - top_left.y), text, color,
            static_cast<float>(scale));
}

}  // namespace impulse2d::render

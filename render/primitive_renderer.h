#pragma once
/// @file primitive_renderer.h
/// The batched GL implementation of core's `DebugDraw`: every primitive of a frame becomes
/// one point sprite (a quad when large) of one vertex buffer; primitives are drawn layer by
/// layer and, within a layer, kind by kind, each kind by its own program in one or a few
/// draw calls.

#include "core/debug_draw.h"
#include "render/camera.h"
#include "render/primitive_shaders.h"
#include "render/primitive_vertices.h"
#include "render/software_raster.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace impulse2d::render {

class ShaderProgram;

/// Sizes of the drawn marks, in screen pixels so they read the same at any zoom.
struct PrimitiveStyle {
  float line_width = 1.5f;         ///< segments, arrow shafts, outlines, orientation marks
  float arrow_head_length = 7.0f;  ///< at most half the arrow's length
  float arrow_head_width = 6.0f;   ///< full width of the head at its base
  int label_scale = 1;             ///< integer magnification of `draw_text` labels (1 = 7 px caps)
  float point_scale = 1.0f;        ///< factor on `draw_point` sizes (dots are given at frame scale 1)
  /// Largest primitive, in pixels across, drawn as one point sprite (the driver's limit
  /// also applies); larger ones are quads. The pixels are the same either way.
  float max_point_sprite = 255.0f;
};

/// Draws world primitives (segments, bands, rectangle outlines, arrows, discs with their rim,
/// convex polygons of up to `polygon_primitive_edges` edges with their outline, runs of up to
/// `text_run_columns` font pixels of text: each one primitive with analytic anti-aliased
/// coverage; fills of larger polygons as triangles) and screen-space rectangles and text, batched between `begin` and `finish`.
/// llvmpipe's cost grows with the primitives it rasterises, the 4x4 pixel blocks each one
/// touches and the work of the fragment program on each block, so a small primitive is a
/// single point sprite rather than two triangles, and each kind of primitive has a program
/// of its own. Draw order: layers (`next_layer`) in the order begun; within a layer, the
/// kinds in `PrimitiveKind` order (polygons, fill triangles, discs, boxes, arrows, text);
/// within a kind, the order emitted. Layers from `start_software_layers` on are rasterised
/// on the CPU (software_raster.h) into the frame read back from GL. Needs the GL context it was created under to be current
/// for construction, `finish` and destruction.
class PrimitiveRenderer final : public DebugDraw {
 public:
  /// Compiles the program and creates the buffers. Throws `RenderError` on shader errors.
  explicit PrimitiveRenderer(const PrimitiveStyle& style = PrimitiveStyle{});
  ~PrimitiveRenderer() override;
  PrimitiveRenderer(const PrimitiveRenderer&) = delete;
  PrimitiveRenderer& operator=(const PrimitiveRenderer&) = delete;

  /// Starts a frame seen through `camera`; drops anything batched before.
  void begin(const Camera& camera);
  /// Starts a new layer: primitives emitted from now on are drawn over those emitted before.
  void next_layer();
  /// Primitives emitted from now on (the layer begun by the last `next_layer` and every
  /// later one) are rasterised on the CPU by `draw_software_layers`, over what `finish`
  /// draws with GL; until `begin`.
  void start_software_layers();
  /// Clears the framebuffer to `background` (drawn opaque) and draws the GL layers of the
  /// batch, in order. Throws `RenderError` when GL reports an error.
  void finish(Color background);
  /// Blends the CPU layers, in order, over `frame`: the GL layers as read back after
  /// `finish` (same size as the camera's). Pixels match GL's to a few levels (rounding).
  void draw_software_layers(Frame& frame);
  /// Threads that rasterise the CPU layers (the caller included).
  int software_thread_count() const { return software_raster_.thread_count(); }
  /// Primitives (point sprites, quads and polygon-fill quads) batched since `begin`.
  std::size_t primitive_count() const { return primitive_count_; }
  /// Width of the frame being batched, pixels.
  int viewport_width() const { return camera_.width(); }
  /// Height of the frame being batched, pixels.
  int viewport_height() const { return camera_.height(); }
  /// The style in use.
  const PrimitiveStyle& style() const { return style_; }
  /// The camera of the frame being batched (set by `begin`).
  const Camera& camera() const { return camera_; }

  // DebugDraw, world coordinates (metres, y up).
  void draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) override;
  void draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) override;
  void draw_segment(vec2 from, vec2 to, Color color) override;
  void draw_arrow(vec2 from, vec2 to, Color color) override;
  void draw_point(vec2 position, float size_pixels, Color color) override;
  void draw_text(vec2 position, const std::string& text, Color color) override;

  /// A straight band `width_pixels` wide from `from` to `to` (metres), ending square at both
  /// (a penetration bar): one primitive.
  void draw_band(vec2 from, vec2 to, float width_pixels, Color color);
  /// The outline of the axis-aligned rectangle [lower, upper] (metres), one line wide and
  /// centred on its edges: one primitive.
  void draw_box_outline(vec2 lower, vec2 upper, Color color);
  /// A filled rectangle in screen pixels: top-left corner and size (y down).
  void draw_screen_rect(vec2 top_left, vec2 size, Color color);
  /// Text in screen pixels with its top-left corner at `top_left` (y down), magnified by
  /// the integer `scale`.
  void draw_screen_text(vec2 top_left, const std::string& text, Color color, int scale);

 private:
  // Consecutive vertices of one kind's buffer drawn by one call, as points or as quads
  // (four vertices each).
  struct Run {
    PrimitiveKind kind = PrimitiveKind::polygon;
    bool points = true;
    std::size_t first_vertex = 0;  // in the kind's vertices
    std::size_t vertices = 0;
  };
  // The primitives of one kind batched in this frame, and the runs of the open layer.
  template <typename V>
  struct Batch {
    std::vector<V> vertices;
    std::vector<Run> open_runs;
  };
  // What covers a primitive of `area` square pixels whose window-space bounds are
  // [lower, upper]: one point sprite, or (when false) a quad. `after_point`: the open run of
  // its kind is of point sprites.
  bool fits_point_sprite(vec2 lower, vec2 upper, float area, bool after_point) const;
  vec2 to_window(vec2 world) const;
  // The batch of a kind drawn with `ShapeVertex` (solid, disc, box, arrow).
  Batch<ShapeVertex>& batch(PrimitiveKind kind) { return batches_[static_cast<int>(kind) - 1]; }
  template <typename V>
  void push_vertex(Batch<V>& batch, PrimitiveKind kind, const V& shape, vec2 position, float point_size, bool point);
  // One primitive covering the axis-aligned window rectangle [lower, upper] of `area` square
  // pixels: a point sprite or a quad (`fits_point_sprite`).
  template <typename V>
  void push_bounded(Batch<V>& batch, PrimitiveKind kind, const V& shape, vec2 lower, vec2 upper, float area);
  void push_quad(PrimitiveKind kind, const ShapeVertex& shape, const vec2 (&corners)[4]);
  void push_shape(PrimitiveKind kind, const ShapeVertex& shape, vec2 lower, vec2 upper);
  void push_filled_triangles(const vec2* window_vertices, int count, Color fill);
  void push_segment(vec2 from, vec2 to, float extension_pixels, float width_pixels, Color color);
  void push_disc(vec2 center, float radius_pixels, Color fill, float ring_radius_pixels, Color ring);
  // A box kind primitive (window pixels): filled, or only an outline `outline_width` wide.
  void push_box(vec2 middle, vec2 half, float outline_width, Color color);
  void push_rect(vec2 lower_left, vec2 upper_right, Color color);
  void push_text(vec2 window_top_left, const std::string& text, Color color, float scale);
  // Adds a CPU-layer primitive of `kind` with parameters `shape` covering the window rectangle
  // [lower, upper] to the open layer (nothing when no pixel centre of the frame lies in it).
  // Returns the primitive added, or nullptr.
  template <typename V>
  SoftwarePrimitive* push_software(PrimitiveKind kind, const V& shape, vec2 lower, vec2 upper);
  // Appends `shape` to the CPU batch's parameters of its kind; returns its index there.
  template <typename V>
  std::uint32_t add_software_parameters(const V& shape);

  PrimitiveStyle style_;
  Camera camera_;
  float world_to_window_[4] = {1.0f, 0.0f, 1.0f, 0.0f};  // x scale, x offset, y scale, y offset
  float max_point_size_ = 1.0f;                           // the driver's largest point sprite
  std::unique_ptr<ShaderProgram> programs_[primitive_kind_count];
  int viewport_locations_[primitive_kind_count] = {};
  unsigned int vertex_arrays_[3] = {};   // polygon vertices, `ShapeVertex`es, text vertices
  unsigned int vertex_buffers_[3] = {};  // the same
  unsigned int index_buffer_ = 0;
  std::size_t capacity_vertices_[3] = {};  // vertices each vertex buffer holds
  std::size_t capacity_quads_ = 0;         // quads the index buffer indexes
  std::size_t primitive_count_ = 0;
  Batch<PolygonVertex> polygons_;
  Batch<ShapeVertex> batches_[primitive_kind_count - 2];  // solid, disc, box, arrow
  Batch<TextVertex> texts_;
  std::vector<Run> runs_;  // of the closed layers, in drawing order
  bool software_layers_ = false;  // primitives go to the CPU batch (start_software_layers)
  SoftwareBatch software_;        // the CPU layers' primitives of the closed layers, in order
  std::vector<SoftwarePrimitive> software_open_[primitive_kind_count];  // the open layer's, by kind
  SoftwareRaster software_raster_;
};

}  // namespace impulse2d::render

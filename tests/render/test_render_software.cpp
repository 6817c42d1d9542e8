// The CPU rasteriser of the overlay layers: frames independent of the thread count and of
// the run, exact coverage where the formulas give it, clipping at the frame's edges, rows
// flipped like GL's read-back, and pixels within a few levels of llvmpipe's.
#include "render/camera.h"
#include "render/easy_font.h"
#include "render/frame_renderer.h"
#include "render/primitive_renderer.h"
#include "render/software_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 120;

// A frame of one opaque colour.
Frame filled_frame(int width, int height, std::uint8_t grey) {
  Frame frame;
  frame.resize(width, height);
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
    frame.rgba[i] = grey;
    frame.rgba[i + 1] = static_cast<std::uint8_t>(255 - grey);
    frame.rgba[i + 2] = grey;
    frame.rgba[i + 3] = 255;
  }
  return frame;
}

// A small deterministic generator (no library distribution, so the batch is the same everywhere).
struct Lcg {
  std::uint32_t state = 12345u;
  float next() {  // in [0, 1)
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / 16777216.0f;
  }
};

void set_rgba(std::uint8_t (&rgba)[4], Lcg& random) {
  for (std::uint8_t& channel : rgba) channel = static_cast<std::uint8_t>(random.next() * 256.0f);
}

// Adds a primitive covering the window pixels [left, right] x [bottom, top], clipped to the frame.
void add(SoftwareBatch& batch, PrimitiveKind kind, std::uint32_t index, float cx, float cy, float reach) {
  SoftwarePrimitive primitive;
  primitive.kind = kind;
  primitive.index = index;
  primitive.left = std::max(0, static_cast<int>(cx - reach));
  primitive.right = std::min(kWidth - 1, static_cast<int>(cx + reach));
  primitive.bottom = std::max(0, static_cast<int>(cy - reach));
  primitive.top = std::min(kHeight - 1, static_cast<int>(cy + reach));
  if (primitive.left <= primitive.right && primitive.bottom <= primitive.top) batch.primitives.push_back(primitive);
}

// Hundreds of overlapping translucent primitives of every kind, many across band edges.
SoftwareBatch mixed_batch() {
  SoftwareBatch batch;
  Lcg random;
  for (int i = 0; i < 400; ++i) {
    const float cx = random.next() * kWidth;
    const float cy = random.next() * kHeight;
    const float size = 1.0f + random.next() * 20.0f;
    const float angle_x = random.next() * 2.0f - 1.0f;
    const float angle_y = std::max(0.05f, 1.0f - angle_x * angle_x);
    const float norm = std::sqrt(angle_x * angle_x + angle_y * angle_y);
    switch (i % 5) {
      case 0:
      case 1:
      case 2: {
        ShapeVertex shape;
        shape.frame[0] = cx;
        shape.frame[1] = cy;
        shape.frame[2] = angle_x / norm;
        shape.frame[3] = angle_y / norm;
        set_rgba(shape.fill, random);
        set_rgba(shape.line, random);
        PrimitiveKind kind = PrimitiveKind::box;
        if (i % 5 == 0) {
          kind = PrimitiveKind::disc;
          shape.disc[0] = size;
          shape.disc[1] = size + 0.75f;
          shape.disc[2] = size - 0.75f;
        } else {
          shape.box[0] = size;
          shape.box[1] = 0.75f + 0.1f * size;
          shape.box[3] = i % 3 == 0 ? 1.5f : 0.0f;
          if (i % 5 == 2) {
            kind = PrimitiveKind::arrow;
            shape.head[0] = size - 3.0f;
            shape.head[1] = size + 4.0f;
            shape.head[2] = 0.6f;
            shape.head[3] = 0.8f;
          }
        }
        batch.shapes.push_back(shape);
        add(batch, kind, static_cast<std::uint32_t>(batch.shapes.size() - 1), cx, cy, size + 8.0f);
        break;
      }
      case 3: {
        TextVertex run;
        run.run[0] = std::floor(cx);
        run.run[1] = std::floor(cy);
        run.run[2] = 20.0f;
        run.run[3] = 9.0f;
        set_rgba(run.fill, random);
        for (std::uint32_t& word : run.bits) word = static_cast<std::uint32_t>(random.next() * 4294967040.0f);
        batch.texts.push_back(run);
        add(batch, PrimitiveKind::text, static_cast<std::uint32_t>(batch.texts.size() - 1), cx + 10.0f, cy - 4.5f, 12.0f);
        break;
      }
      default: {
        PolygonVertex polygon;
        polygon.origin[0] = cx;
        polygon.origin[1] = cy;
        polygon.origin[2] = 0.75f;
        for (int edge = 0; edge < polygon_primitive_edges; ++edge) {
          const float turn = 0.785398f * static_cast<float>(edge);
          polygon.edges[edge][0] = std::cos(turn);
          polygon.edges[edge][1] = std::sin(turn);
          polygon.edges[edge][2] = size;
        }
        set_rgba(polygon.fill, random);
        set_rgba(polygon.line, random);
        batch.polygons.push_back(polygon);
        add(batch, PrimitiveKind::polygon, static_cast<std::uint32_t>(batch.polygons.size() - 1), cx, cy, size + 3.0f);
        break;
      }
    }
  }
  FillQuad quad{{vec2(10.0f, 10.0f), vec2(70.0f, 15.0f), vec2(60.5f, 80.5f), vec2(12.0f, 70.0f)}};
  quad.fill[0] = 200;
  quad.fill[3] = 128;
  batch.fill_quads.push_back(quad);
  add(batch, PrimitiveKind::solid, 0, 40.0f, 45.0f, 36.0f);
  return batch;
}

Frame draw_with_threads(const SoftwareBatch& batch, int threads) {
  Frame frame = filled_frame(kWidth, kHeight, 40);
  SoftwareRaster raster(threads);
  EXPECT_EQ(raster.thread_count(), std::max(threads, 1));
  raster.draw(batch, frame);
  return frame;
}

// One opaque white box (not an outline) with half extents `half` at window (x, y).
SoftwareBatch one_box(float x, float y, float half_x, float half_y) {
  SoftwareBatch batch;
  ShapeVertex shape;
  shape.frame[0] = x;
  shape.frame[1] = y;
  shape.box[0] = half_x;
  shape.box[1] = half_y;
  std::fill(std::begin(shape.fill), std::end(shape.fill), std::uint8_t{255});
  batch.shapes.push_back(shape);
  SoftwarePrimitive primitive;
  primitive.kind = PrimitiveKind::box;
  primitive.left = static_cast<int>(x - half_x - 1.0f);
  primitive.right = static_cast<int>(x + half_x + 1.0f);
  primitive.bottom = static_cast<int>(y - half_y - 1.0f);
  primitive.top = static_cast<int>(y + half_y + 1.0f);
  batch.primitives.push_back(primitive);
  return batch;
}

}  // namespace

TEST(RenderSoftware, FramesDoNotDependOnThreadCountOrRun) {
  const SoftwareBatch batch = mixed_batch();
  ASSERT_GT(batch.primitives.size(), 350u);
  const Frame one = draw_with_threads(batch, 1);
  EXPECT_NE(one.hash(), filled_frame(kWidth, kHeight, 40).hash());
  for (const int threads : {1, 2, 4}) {
    for (int run = 0; run < 2; ++run) {
      EXPECT_TRUE(draw_with_threads(batch, threads).rgba == one.rgba) << threads << " threads, run " << run;
    }
  }
}

TEST(RenderSoftware, BoxCoverageIsExact) {
  // A white box over black, centred on pixel (20, 10)'s centre with half extents 3 x 2: pixels
  // whose centres lie 2.5 or more inside an edge are white; the ones whose centres lie on the
  // edge get half coverage (128); from half a pixel beyond it, nothing.
  Frame frame = filled_frame(40, 20, 0);
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) frame.rgba[i + 1] = 0;  // black
  SoftwareRaster raster(2);
  raster.draw(one_box(20.5f, 10.5f, 3.0f, 2.0f), frame);
  const auto at = [&](int column, int window_row) { return frame.pixel(column, frame.height - 1 - window_row); };
  EXPECT_EQ(at(20, 10), (Pixel{255, 255, 255, 255}));
  EXPECT_EQ(at(22, 11), (Pixel{255, 255, 255, 255}));
  EXPECT_EQ(at(23, 10), (Pixel{128, 128, 128, 255}));  // centre on the right edge
  EXPECT_EQ(at(20, 12), (Pixel{128, 128, 128, 255}));  // centre on the top edge
  EXPECT_EQ(at(23, 12), (Pixel{64, 64, 64, 255}));     // both: a quarter
  EXPECT_EQ(at(24, 10), (Pixel{0, 0, 0, 255}));
  EXPECT_EQ(at(20, 13), (Pixel{0, 0, 0, 255}));
  EXPECT_EQ(at(16, 10), (Pixel{0, 0, 0, 255}));
}

TEST(RenderSoftware, TranslucentBlendIsPremultipliedOver) {
  // Half-transparent red over opaque grey 100: red 0.5 * 255 + 100 * 0.5 rounds to 178, the
  // others to 50, alpha stays 255.
  Frame frame = filled_frame(10, 10, 100);
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) frame.rgba[i + 1] = 100;
  SoftwareBatch batch = one_box(5.0f, 5.0f, 3.0f, 3.0f);
  batch.shapes[0].fill[1] = 0;
  batch.shapes[0].fill[2] = 0;
  batch.shapes[0].fill[3] = 128;
  SoftwareRaster raster(1);
  raster.draw(batch, frame);
  EXPECT_EQ(frame.pixel(5, 5), (Pixel{178, 50, 50, 255}));
}

namespace {

constexpr Color kBackground{0.1f, 0.1f, 0.1f, 1.0f};
constexpr Color kMark{0.9f, 0.5f, 0.2f, 1.0f};

// 200x100 pixels, 10 pixels per metre, world origin at the centre.
Camera test_camera() { return Camera::centered(vec2(0.0f, 0.0f), 10.0f, 200, 100); }

// Marks of every kind a CPU layer draws, some of them across the frame's edges.
void draw_marks(PrimitiveRenderer& draw) {
  const vec2 triangle[3] = {{5.0f, -4.0f}, {8.3f, -3.1f}, {6.2f, -0.4f}};
  draw.draw_solid_polygon(triangle, 3, kMark, Color{0.0f, 0.0f, 0.0f, 1.0f});
  // More edges than a polygon primitive has: fill triangles (the solid kind) and edge segments.
  vec2 decagon[10];
  for (int i = 0; i < 10; ++i) {
    const float turn = 0.6283185f * static_cast<float>(i) + 0.1f;
    decagon[i] = vec2(-6.3f + 2.7f * std::cos(turn), -1.1f + 2.7f * std::sin(turn));
  }
  draw.draw_solid_polygon(decagon, 10, Color{0.3f, 0.3f, 0.8f, 0.6f}, kMark);
  draw.draw_solid_circle({-5.0f, 2.0f}, 1.5f, {1.0f, 0.0f}, Color{0.2f, 0.6f, 0.4f, 0.7f}, kMark);
  draw.draw_segment({-9.5f, -4.5f}, {9.5f, 4.5f}, kMark);
  draw.draw_arrow({1.0f, 0.0f}, {4.0f, 2.0f}, kMark);
  draw.draw_box_outline({-8.0f, -4.0f}, {-2.0f, -1.0f}, kMark);
  draw.draw_band({-3.0f, 3.0f}, {-1.0f, 4.0f}, 3.0f, kMark);
  draw.draw_point({2.0f, -3.0f}, 6.0f, kMark);
  draw.draw_text({-1.0f, -2.0f}, "012 CPU", kMark);
  draw.draw_screen_text({4.0f, 4.0f}, "HUD", kMark, 1);
  // Across the edges: the right edge, the bottom-left corner, the top.
  draw.draw_solid_circle({10.0f, 0.0f}, 1.0f, {0.0f, 1.0f}, kMark, kMark);
  draw.draw_solid_circle({-10.0f, -5.0f}, 1.2f, {0.0f, 1.0f}, kMark, kMark);
  draw.draw_segment({-3.0f, 4.5f}, {3.0f, 6.0f}, kMark);
}

Frame render_marks(bool on_cpu) {
  FrameRenderer renderer(200, 100);
  Frame frame;
  renderer.render_primitives(test_camera(), kBackground,
                             [&](PrimitiveRenderer& draw) {
                               draw.next_layer();
                               if (on_cpu) draw.start_software_layers();
                               draw_marks(draw);
                             },
                             frame);
  return frame;
}

}  // namespace

TEST(RenderSoftware, MatchesLlvmpipeWithinRounding) {
  const Frame gl = render_marks(false);
  const Frame cpu = render_marks(true);
  ASSERT_EQ(gl.rgba.size(), cpu.rgba.size());
  int largest_delta = 0;
  int differing = 0;
  for (std::size_t i = 0; i < gl.rgba.size(); ++i) {
    const int delta = std::abs(static_cast<int>(gl.rgba[i]) - static_cast<int>(cpu.rgba[i]));
    largest_delta = std::max(largest_delta, delta);
    differing += delta != 0 ? 1 : 0;
  }
  EXPECT_LE(largest_delta, 2) << differing << " channels differ";
  EXPECT_EQ(render_marks(true).hash(), cpu.hash());  // the CPU frame repeats
}

TEST(RenderSoftware, ClippedMarksStayInsideTheFrameAndRowsAreNotFlipped) {
  // Only marks across the edges: a disc on the right edge must not wrap into the left
  // column of its rows, one on the bottom-left corner lands in the bottom rows of the frame
  // (row 0 is the top), and nothing reaches the rows far from either.
  FrameRenderer renderer(200, 100);
  Frame frame;
  renderer.render_primitives(test_camera(), kBackground,
                             [&](PrimitiveRenderer& draw) {
                               draw.start_software_layers();
                               draw.draw_solid_circle({10.0f, 0.0f}, 1.0f, {0.0f, 1.0f}, kMark, kMark);
                               draw.draw_solid_circle({-10.0f, -5.0f}, 1.2f, {0.0f, 1.0f}, kMark, kMark);
                             },
                             frame);
  const Pixel background = frame.pixel(100, 50);
  EXPECT_NE(frame.pixel(199, 50), background);  // right-edge disc, drawn
  for (int row = 35; row < 65; ++row) EXPECT_EQ(frame.pixel(0, row), background) << "row " << row;
  EXPECT_NE(frame.pixel(0, 99), background);  // bottom-left disc, in the bottom row
  for (int column = 0; column < 200; ++column) EXPECT_EQ(frame.pixel(column, 0), background) << column;
}

TEST(RenderSoftware, MarksFarBeyondOrNotFiniteAreClippedOrDropped) {
  // A band from 1e15 m left of the frame to 1e15 m right of it covers its row from the first
  // column to the last; a band wholly right of the frame, and marks at NaN or infinite
  // positions, touch nothing (their pixel bounds are empty, not wrapped or overflowed).
  const float far = 1.0e15f;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float infinity = std::numeric_limits<float>::infinity();
  FrameRenderer renderer(200, 100);
  Frame frame;
  renderer.render_primitives(test_camera(), kBackground,
                             [&](PrimitiveRenderer& draw) {
                               draw.start_software_layers();
                               draw.draw_band({-far, 0.0f}, {far, 0.0f}, 4.0f, kMark);
                               draw.draw_band({11.0f, 2.0f}, {far, 2.0f}, 4.0f, kMark);
                               draw.draw_point({nan, 3.0f}, 6.0f, kMark);
                               draw.draw_point({-infinity, 3.0f}, 6.0f, kMark);
                               draw.draw_segment({0.0f, nan}, {1.0f, 3.0f}, kMark);
                               draw.draw_arrow({-5.0f, 3.0f}, {infinity, 3.0f}, kMark);
                             },
                             frame);
  Frame empty;
  renderer.render_primitives(test_camera(), kBackground, [](PrimitiveRenderer& draw) { draw.start_software_layers(); },
                             empty);
  const Pixel background = empty.pixel(100, 50);
  for (int column = 0; column < 200; ++column) {
    EXPECT_NE(frame.pixel(column, 50), background) << "column " << column << " of the band's row";
  }
  for (int row = 0; row < 100; ++row) {
    if (row >= 47 && row <= 52) continue;  // the band: 4 px wide about row 50's top edge
    for (int column = 0; column < 200; ++column) {
      ASSERT_EQ(frame.pixel(column, row), empty.pixel(column, row)) << "column " << column << ", row " << row;
    }
  }
}

namespace {

// The text fragment program's coverage (primitive_shaders.cpp) at the centre of pixel (column,
// window row), one pixel at a time: ink under the centre times the run's anti-aliased inside.
float text_coverage(const TextVertex& run, int column, int row) {
  const float qx = static_cast<float>(column) + 0.5f - run.run[0];
  const float qy = run.run[1] - (static_cast<float>(row) + 0.5f);
  const auto saturate = [](float value) { return std::min(std::max(value, 0.0f), 1.0f); };
  const float inside = saturate(std::min(qx, run.run[2] - qx) + 0.5f) * saturate(std::min(qy, run.run[3] - qy) + 0.5f);
  if (!(inside > 0.0f)) return 0.0f;
  const int font_column = std::min(static_cast<int>(qx * run.font_scale), 31);
  const int font_row = std::min(static_cast<int>(qy * run.font_scale), font_glyph_rows - 1);
  const int bit = std::min(std::max(font_column * font_glyph_rows + font_row, 0), 255);
  return inside * static_cast<float>((run.bits[bit / 32] >> (bit % 32)) & 1u);
}

// `fill` over `coverage(column, row)` of each pixel of `primitive`'s bounds, blended premultiplied
// over `frame` pixel by pixel as GL blends a fragment program's output: the reference the
// rasteriser's bytes are held to.
template <typename Coverage>
void blend_by_pixel(const std::uint8_t (&fill)[4], const SoftwarePrimitive& primitive, const Coverage& coverage,
                    Frame& frame) {
  for (int row = primitive.bottom; row <= primitive.top; ++row) {
    for (int column = primitive.left; column <= primitive.right; ++column) {
      const float alpha = static_cast<float>(fill[3]) / 255.0f * coverage(column, row);
      if (!(alpha > 0.0f)) continue;
      std::uint8_t* const pixel = frame.rgba.data() + (static_cast<std::size_t>(frame.height - 1 - row) *
                                                           static_cast<std::size_t>(frame.width) +
                                                       static_cast<std::size_t>(column)) * 4;
      for (int channel = 0; channel < 3; ++channel) {
        const float source = static_cast<float>(fill[channel]) / 255.0f * alpha;
        const float blended = source + static_cast<float>(pixel[channel]) / 255.0f * (1.0f - alpha);
        pixel[channel] = static_cast<std::uint8_t>(std::min(blended, 1.0f) * 255.0f + 0.5f);
      }
    }
  }
}

// Sets `primitive`'s bounds to the pixels of a `width` x `height` frame whose centres lie in the
// window rectangle [lower, upper]; false when there are none.
bool cover(SoftwarePrimitive& primitive, vec2 lower, vec2 upper, int width, int height) {
  primitive.left = std::max(0, static_cast<int>(std::ceil(lower.x - 0.5f)));
  primitive.right = std::min(width - 1, static_cast<int>(std::floor(upper.x - 0.5f)));
  primitive.bottom = std::max(0, static_cast<int>(std::ceil(lower.y - 0.5f)));
  primitive.top = std::min(height - 1, static_cast<int>(std::floor(upper.y - 0.5f)));
  return primitive.left <= primitive.right && primitive.bottom <= primitive.top;
}

// An opaque frame of random colours.
Frame random_opaque_frame(int width, int height, Lcg& random) {
  Frame frame;
  frame.resize(width, height);
  for (std::size_t i = 0; i < frame.rgba.size(); ++i) {
    frame.rgba[i] = i % 4 == 3 ? 255 : static_cast<std::uint8_t>(random.next() * 256.0f);
  }
  return frame;
}

// How many bytes of two frames of one size differ, and the first that does.
struct ByteDifference {
  std::size_t count = 0;
  std::size_t first = 0;
};
ByteDifference byte_difference(const Frame& a, const Frame& b) {
  ByteDifference difference{0, a.rgba.size()};
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (a.rgba[i] == b.rgba[i]) continue;
    ++difference.count;
    difference.first = std::min(difference.first, i);
  }
  return difference;
}

// Expects `batch` drawn over `background` to give `expected`'s bytes at four and eight lanes, on
// 1 and 3 threads.
void expect_formulas_bytes(const SoftwareBatch& batch, const Frame& background, const Frame& expected) {
  for (const RasterLanes lanes : {RasterLanes::four, RasterLanes::eight}) {
    for (const int threads : {1, 3}) {
      Frame frame = background;
      SoftwareRaster(threads, lanes).draw(batch, frame);
      const ByteDifference difference = byte_difference(frame, expected);
      EXPECT_EQ(difference.count, 0u) << (lanes == RasterLanes::eight ? "eight" : "four") << " lanes, " << threads
                                      << " threads: first differing byte " << difference.first << " (pixel "
                                      << difference.first / 4 % static_cast<std::size_t>(frame.width) << ", "
                                      << difference.first / 4 / static_cast<std::size_t>(frame.width)
                                      << " from the top)";
    }
  }
}

}  // namespace

// Labels and the HUD place text in whole pixels, and their colours are opaque: the rasteriser
// paints such runs without blending (coverage is exactly 0 or 1 there). The bytes must be the
// formula's, at scales 1 to 3, across the frame's edges (a right edge no multiple of eight
// pixels away), overlapping, at either lane width and any thread count.
TEST(RenderSoftware, OpaqueTextInWholePixelsGivesTheFormulasBytes) {
  constexpr int width = 203;
  constexpr int height = 77;
  Lcg random;
  const Frame background = random_opaque_frame(width, height, random);
  SoftwareBatch batch;
  Frame expected = background;
  for (int i = 0; i < 80; ++i) {
    TextVertex run;
    const int scale = 1 + i % 3;
    run.font_scale = 1.0f / static_cast<float>(scale);
    run.run[0] = std::floor(random.next() * 230.0f) - 15.0f;
    run.run[1] = std::floor(random.next() * 110.0f) - 10.0f;
    run.run[2] = static_cast<float>((1 + static_cast<int>(random.next() * text_run_columns)) * scale);
    run.run[3] = static_cast<float>(font_glyph_rows * scale);
    set_rgba(run.fill, random);
    run.fill[3] = 255;
    for (std::uint32_t& word : run.bits) word = static_cast<std::uint32_t>(random.next() * 4294967040.0f);
    // The pixels a push_text run may touch: a pixel's margin around it, clipped to the frame.
    SoftwarePrimitive primitive;
    primitive.kind = PrimitiveKind::text;
    if (!cover(primitive, vec2(run.run[0], run.run[1] - run.run[3]) - 1.0f,
               vec2(run.run[0] + run.run[2], run.run[1]) + 1.0f, width, height)) {
      continue;
    }
    primitive.index = static_cast<std::uint32_t>(batch.texts.size());
    batch.texts.push_back(run);
    batch.primitives.push_back(primitive);
    blend_by_pixel(run.fill, primitive, [&](int column, int row) { return text_coverage(run, column, row); },
                   expected);
  }
  ASSERT_GT(batch.primitives.size(), 60u);
  ASSERT_GT(byte_difference(expected, background).count, 3000u);
  expect_formulas_bytes(batch, background, expected);
}

namespace {

// The box fragment program's coverage at window point (x, y) for an axis-aligned box centred on
// (cx, cy): `rectangle` of the half extents, less that of the hole for an outline.
float axis_box_coverage(const ShapeVertex& shape, float x, float y) {
  const float px = x - shape.frame[0];
  const float py = y - shape.frame[1];
  const auto saturate = [](float value) { return std::min(std::max(value, 0.0f), 1.0f); };
  const auto rectangle = [&](float hx, float hy) {
    return saturate(hx + 0.5f - std::abs(px)) * saturate(hy + 0.5f - std::abs(py));
  };
  float coverage = rectangle(shape.box[0], shape.box[1]);
  if (shape.box[3] > 0.0f) coverage = coverage - rectangle(shape.box[0] - shape.box[3], shape.box[1] - shape.box[3]);
  return coverage;
}

}  // namespace

// Bounding boxes, panels and highlights are axis-aligned boxes, filled or outlines: the
// rasteriser finds each row's and each column's factor once and skips an outline's hole. The
// bytes must be the formula's, pixel by pixel, for boxes of every size from under a pixel to
// wider than a band, outlines as thick as the box or thinner than a pixel, across the frame's
// edges, at either lane width and any thread count.
TEST(RenderSoftware, AxisAlignedBoxesGiveTheFormulasBytes) {
  constexpr int width = 203;
  constexpr int height = 77;
  Lcg random;
  const Frame background = random_opaque_frame(width, height, random);
  SoftwareBatch batch;
  Frame expected = background;
  for (int i = 0; i < 300; ++i) {
    ShapeVertex shape;
    shape.frame[0] = random.next() * 230.0f - 15.0f;
    shape.frame[1] = random.next() * 100.0f - 10.0f;
    shape.frame[2] = 1.0f;
    shape.frame[3] = 0.0f;
    const float size = i % 10 == 0 ? 20.0f + random.next() * 30.0f : 0.2f + random.next() * 12.0f;
    shape.box[0] = size * (0.3f + random.next());
    shape.box[1] = size * (0.3f + random.next());
    shape.box[3] = i % 3 == 0 ? 0.0f : 0.25f + random.next() * 0.5f * std::min(shape.box[0], shape.box[1]) * 2.2f;
    set_rgba(shape.fill, random);
    if (i % 4 == 0) shape.fill[3] = 255;
    // The pixels it may touch: the box grown by a pixel, clipped to the frame.
    SoftwarePrimitive primitive;
    primitive.kind = PrimitiveKind::box;
    primitive.frame_lower = vec2(-shape.box[0] - 1.0f, -shape.box[1] - 1.0f);
    primitive.frame_upper = vec2(shape.box[0] + 1.0f, shape.box[1] + 1.0f);
    const vec2 centre(shape.frame[0], shape.frame[1]);
    if (!cover(primitive, centre + primitive.frame_lower, centre + primitive.frame_upper, width, height)) continue;
    primitive.index = static_cast<std::uint32_t>(batch.shapes.size());
    batch.shapes.push_back(shape);
    batch.primitives.push_back(primitive);
    blend_by_pixel(shape.fill, primitive,
                   [&](int column, int row) {
                     return axis_box_coverage(shape, static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
                   },
                   expected);
  }
  ASSERT_GT(batch.primitives.size(), 250u);
  ASSERT_GT(byte_difference(expected, background).count, 10000u);
  expect_formulas_bytes(batch, background, expected);
}

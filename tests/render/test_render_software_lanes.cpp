// The CPU rasteriser's eight-lane (AVX2) drawing against its four-lane one: the same RGBA bytes
// for a frame with every kind of primitive, placed as the overlays place them (frame rectangles
// with a margin, rotated and axis-aligned, outlines, rings, spans that end at the frame's right
// edge, which is no multiple of eight pixels away).
#include "render/software_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

constexpr int kFrameWidth = 203;
constexpr int kFrameHeight = 77;

// Deterministic numbers in [0, 1): the same batch on every machine.
class Sequence {
 public:
  float next() {
    state_ = state_ * 747796405u + 2891336453u;
    return static_cast<float>(state_ >> 8) * (1.0f / 16777216.0f);
  }
  float between(float low, float high) { return low + (high - low) * next(); }
  std::uint8_t byte() { return static_cast<std::uint8_t>(next() * 256.0f); }

 private:
  std::uint32_t state_ = 2024u;
};

void colour(std::uint8_t (&rgba)[4], Sequence& sequence) {
  for (std::uint8_t& channel : rgba) channel = sequence.byte();
}

// The pixels whose centres lie in the window rectangle [lower, upper], clipped to the frame, as
// the primitive renderer computes them; false when none.
bool cover(SoftwarePrimitive& primitive, vec2 lower, vec2 upper) {
  primitive.left = std::max(0, static_cast<int>(std::ceil(lower.x - 0.5f)));
  primitive.bottom = std::max(0, static_cast<int>(std::ceil(lower.y - 0.5f)));
  primitive.right = std::min(kFrameWidth - 1, static_cast<int>(std::floor(upper.x - 0.5f)));
  primitive.top = std::min(kFrameHeight - 1, static_cast<int>(std::floor(upper.y - 0.5f)));
  return primitive.left <= primitive.right && primitive.bottom <= primitive.top;
}

// A disc, box or arrow whose frame rectangle is [lower, upper] grown by half a pixel.
void add_shape(SoftwareBatch& batch, PrimitiveKind kind, const ShapeVertex& shape, vec2 lower, vec2 upper) {
  SoftwarePrimitive primitive;
  primitive.kind = kind;
  primitive.frame_lower = lower - 0.5f;
  primitive.frame_upper = upper + 0.5f;
  const vec2 origin(shape.frame[0], shape.frame[1]);
  const vec2 axis(shape.frame[2], shape.frame[3]);
  const vec2 normal(-axis.y, axis.x);
  vec2 window_lower(1.0e30f);
  vec2 window_upper(-1.0e30f);
  for (const vec2 corner : {primitive.frame_lower, primitive.frame_upper, vec2(primitive.frame_lower.x, primitive.frame_upper.y),
                            vec2(primitive.frame_upper.x, primitive.frame_lower.y)}) {
    const vec2 window = origin + axis * corner.x + normal * corner.y;
    window_lower = glm::min(window_lower, window);
    window_upper = glm::max(window_upper, window);
  }
  if (!cover(primitive, window_lower, window_upper)) return;
  primitive.index = static_cast<std::uint32_t>(batch.shapes.size());
  batch.shapes.push_back(shape);
  batch.primitives.push_back(primitive);
}

// Hundreds of translucent primitives of every kind, a third of the shapes axis-aligned.
SoftwareBatch every_kind() {
  SoftwareBatch batch;
  Sequence sequence;
  for (int i = 0; i < 700; ++i) {
    // One statement per number: the order in which a call's arguments are evaluated differs
    // between compilers, and the batch must not.
    const float centre_x = sequence.between(-10.0f, kFrameWidth + 10.0f);
    const vec2 centre(centre_x, sequence.between(-10.0f, kFrameHeight + 10.0f));
    const float angle = i % 3 == 0 ? 0.0f : sequence.between(0.0f, 6.2831853f);
    ShapeVertex shape;
    shape.frame[0] = centre.x;
    shape.frame[1] = centre.y;
    shape.frame[2] = std::cos(angle);
    shape.frame[3] = std::sin(angle);
    colour(shape.fill, sequence);
    colour(shape.line, sequence);
    const float size = sequence.between(0.3f, 24.0f);
    switch (i % 7) {
      case 0: {  // a disc, with a ring every other time
        shape.disc[0] = size;
        const float ring = i % 2 == 0 ? size : 0.0f;
        shape.disc[1] = ring + 0.75f;
        shape.disc[2] = ring - 0.75f;
        const float reach = std::max(shape.disc[0], shape.disc[1]);
        add_shape(batch, PrimitiveKind::disc, shape, vec2(-reach), vec2(reach));
        break;
      }
      case 1:
      case 2: {  // a box: filled, or an outline (bounding boxes, pair segments, bars)
        shape.box[0] = size;
        shape.box[1] = sequence.between(0.3f, 12.0f);
        shape.box[3] = i % 2 == 0 ? sequence.between(0.5f, 2.0f) : 0.0f;
        add_shape(batch, PrimitiveKind::box, shape, -vec2(shape.box[0], shape.box[1]), vec2(shape.box[0], shape.box[1]));
        break;
      }
      case 3: {  // an arrow: shaft and head
        shape.box[0] = size;
        shape.box[1] = sequence.between(0.5f, 2.0f);
        shape.head[0] = size - 4.0f;
        shape.head[1] = size + 3.0f;
        shape.head[2] = 0.6f;
        shape.head[3] = 0.8f;
        // The frame holds every pixel of positive coverage, as `PrimitiveRenderer::draw_arrow`'s
        // does (the rasteriser relies on it): the head from half a pixel before its base, and as
        // far out as its mitred edge reaches (7 * 0.6 / 0.8 + 0.5 (1 + 0.6) / 0.8 - 0.5 = 5.75).
        add_shape(batch, PrimitiveKind::arrow, shape, vec2(std::min(-size, shape.head[0]), -5.75f),
                  vec2(size + 3.0f, 5.75f));
        break;
      }
      case 4: {  // a text run
        TextVertex run;
        run.run[0] = std::floor(centre.x);
        run.run[1] = std::floor(centre.y);
        run.run[2] = sequence.between(4.0f, 40.0f);
        run.run[3] = 9.0f;
        colour(run.fill, sequence);
        for (std::uint32_t& word : run.bits) word = static_cast<std::uint32_t>(sequence.next() * 4294967040.0f);
        SoftwarePrimitive primitive;
        primitive.kind = PrimitiveKind::text;
        if (!cover(primitive, vec2(run.run[0], run.run[1] - run.run[3]), vec2(run.run[0] + run.run[2], run.run[1]))) break;
        primitive.index = static_cast<std::uint32_t>(batch.texts.size());
        batch.texts.push_back(run);
        batch.primitives.push_back(primitive);
        break;
      }
      case 5: {  // a polygon
        PolygonVertex polygon;
        polygon.origin[0] = centre.x;
        polygon.origin[1] = centre.y;
        polygon.origin[2] = 0.75f;
        for (int edge = 0; edge < polygon_primitive_edges; ++edge) {
          const float turn = angle + 0.785398f * static_cast<float>(edge);
          polygon.edges[edge][0] = std::cos(turn);
          polygon.edges[edge][1] = std::sin(turn);
          polygon.edges[edge][2] = size * 0.5f;
        }
        colour(polygon.fill, sequence);
        colour(polygon.line, sequence);
        SoftwarePrimitive primitive;
        primitive.kind = PrimitiveKind::polygon;
        if (!cover(primitive, centre - (size + 2.0f), centre + (size + 2.0f))) break;
        primitive.index = static_cast<std::uint32_t>(batch.polygons.size());
        batch.polygons.push_back(polygon);
        batch.primitives.push_back(primitive);
        break;
      }
      default: {  // a fill quad
        FillQuad quad;
        for (int corner = 0; corner < 4; ++corner) {
          const float turn = angle + 1.5707963f * static_cast<float>(corner);
          quad.corners[corner] = centre + size * vec2(std::cos(turn), std::sin(turn));
        }
        colour(quad.fill, sequence);
        SoftwarePrimitive primitive;
        primitive.kind = PrimitiveKind::solid;
        if (!cover(primitive, centre - size, centre + size)) break;
        primitive.index = static_cast<std::uint32_t>(batch.fill_quads.size());
        batch.fill_quads.push_back(quad);
        batch.primitives.push_back(primitive);
        break;
      }
    }
  }
  return batch;
}

// Hundreds of marks a few pixels across, as the overlays draw them on a crowded scene: dots
// (fill alone), rings alone, dots with a ring, lines and bars at every angle, short arrows, small
// bounding-box outlines; placed anywhere, across band boundaries and the frame's edges. Their
// rows are one group (or two to a group), their spans a few pixels.
SoftwareBatch small_marks() {
  SoftwareBatch batch;
  Sequence sequence;
  for (int i = 0; i < 900; ++i) {
    const float centre_x = sequence.between(-4.0f, kFrameWidth + 4.0f);
    const float centre_y = sequence.between(-4.0f, kFrameHeight + 4.0f);
    const float angle = i % 5 == 0 ? 1.5707963f * static_cast<float>(i % 4) : sequence.between(0.0f, 6.2831853f);
    ShapeVertex shape;
    shape.frame[0] = centre_x;
    shape.frame[1] = centre_y;
    colour(shape.fill, sequence);
    const float size = sequence.between(0.5f, 7.0f);
    switch (i % 6) {
      case 0:
      case 1: {  // a dot, a ring alone, or both
        const int variant = i % 3;
        shape.disc[0] = variant == 1 ? -1.0e6f : size * 0.5f;
        if (variant != 0) {
          colour(shape.line, sequence);
          shape.disc[1] = size * 0.5f + 0.75f;
          shape.disc[2] = size * 0.5f - 0.75f;
        }
        if (variant == 1) shape.fill[3] = 0;
        const float reach = std::max(shape.disc[0], shape.disc[1]);
        add_shape(batch, PrimitiveKind::disc, shape, vec2(-reach), vec2(reach));
        break;
      }
      case 2: {  // a line (0.75 px half width) or a bar (1 to 2 px), rotated
        shape.frame[2] = std::cos(angle);
        shape.frame[3] = std::sin(angle);
        shape.box[0] = size;
        shape.box[1] = i % 4 == 0 ? 0.75f : sequence.between(1.0f, 2.0f);
        add_shape(batch, PrimitiveKind::box, shape, -vec2(shape.box[0], shape.box[1]), vec2(shape.box[0], shape.box[1]));
        break;
      }
      case 3: {  // a short arrow with a head 7 px long and 6 wide (less when short)
        shape.frame[2] = std::cos(angle);
        shape.frame[3] = std::sin(angle);
        const float head = std::min(7.0f, size);
        shape.box[0] = size * 0.5f;
        shape.box[1] = 0.75f;
        shape.head[0] = size * 0.5f;
        shape.head[1] = size * 0.5f + head;
        shape.head[2] = 0.394f;
        shape.head[3] = 0.919f;
        add_shape(batch, PrimitiveKind::arrow, shape, vec2(-shape.box[0], -3.5f), vec2(shape.head[1], 3.5f));
        break;
      }
      default: {  // a bounding-box outline one line (1.5 px) wide
        shape.box[0] = size + 0.75f;
        shape.box[1] = sequence.between(0.5f, 7.0f) + 0.75f;
        shape.box[3] = 1.5f;
        add_shape(batch, PrimitiveKind::box, shape, -vec2(shape.box[0], shape.box[1]), vec2(shape.box[0], shape.box[1]));
        break;
      }
    }
  }
  return batch;
}

// An opaque frame with a different colour at every pixel.
Frame background() {
  Frame frame;
  frame.resize(kFrameWidth, kFrameHeight);
  for (std::size_t i = 0; i < frame.rgba.size(); i += 4) {
    frame.rgba[i] = static_cast<std::uint8_t>(i * 7);
    frame.rgba[i + 1] = static_cast<std::uint8_t>(i / 4);
    frame.rgba[i + 2] = static_cast<std::uint8_t>(255 - i / 8);
    frame.rgba[i + 3] = 255;
  }
  return frame;
}

Frame drawn(const SoftwareBatch& batch, RasterLanes lanes, int threads = 2) {
  SoftwareRaster raster(threads, lanes);
  EXPECT_EQ(raster.lanes(), lanes);
  Frame frame = background();
  raster.draw(batch, frame);
  return frame;
}

}  // namespace

TEST(RenderSoftwareLanes, EightLanesGiveTheBytesOfFour) {
  if (!SoftwareRaster::eight_lanes_available()) GTEST_SKIP() << "this CPU has no AVX2";
  const SoftwareBatch batch = every_kind();
  ASSERT_GT(batch.primitives.size(), 500u);
  const Frame four = drawn(batch, RasterLanes::four);
  const Frame eight = drawn(batch, RasterLanes::eight);
  EXPECT_NE(four.hash(), background().hash());
  ASSERT_EQ(four.rgba.size(), eight.rgba.size());
  std::size_t differing = 0;
  std::size_t first = four.rgba.size();
  for (std::size_t i = 0; i < four.rgba.size(); ++i) {
    if (four.rgba[i] == eight.rgba[i]) continue;
    ++differing;
    first = std::min(first, i);
  }
  EXPECT_EQ(differing, 0u) << "first differing byte " << first << " (pixel " << first / 4 % kFrameWidth << ", "
                           << first / 4 / kFrameWidth << " from the top)";
}

// Marks a few pixels across take their own ways through the rasteriser (a group per row of their
// bounds, two rows or two spans to a group with eight lanes): the frame is the same at either
// width and any thread count, and the same as the rasteriser gave before those ways (24f302d,
// which found each row's columns and drew each span alone).
TEST(RenderSoftwareLanes, SmallMarksGiveTheSameBytesAtAnyWidthAndThreadCount) {
  const SoftwareBatch batch = small_marks();
  ASSERT_GT(batch.primitives.size(), 800u);
  const Frame four = drawn(batch, RasterLanes::four, 1);
  EXPECT_NE(four.hash(), background().hash());
  EXPECT_EQ(four.hash(), drawn(batch, RasterLanes::four, 3).hash());
  if (SoftwareRaster::eight_lanes_available()) {
    EXPECT_EQ(four.hash(), drawn(batch, RasterLanes::eight, 1).hash());
    EXPECT_EQ(four.hash(), drawn(batch, RasterLanes::eight, 3).hash());
  }
  EXPECT_EQ(four.hash(), 0xbdfc7a1d98347930ull) << std::hex << "hash 0x" << four.hash();
}

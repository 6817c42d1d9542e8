#pragma once
/// @file software_raster_lanes.h
/// The CPU rasteriser's drawing of one band of rows (software_raster.h), written once for any
/// number of lanes: discs, boxes, arrows and text runs are shaded and blended F::width pixels of a
/// row at a time with F = Float4 (float4.h) or Float8 (float8.h), every lane doing the IEEE
/// operations the scalar formulas do, so both widths give the same bytes; polygons and fill
/// triangles pixel by pixel.
///
/// Included only by software_raster.cpp (four lanes) and software_raster_8.cpp (eight lanes,
/// compiled for AVX2). Everything here has internal linkage (the unnamed namespace), so the
/// linker never merges an AVX2 copy of a function into code that runs on a CPU without AVX2.
/// The few inline functions of other headers called here (`std::min`, `Image::stride`, vector
/// indexing) are inlined: `nm` of the AVX2 object lists no weak symbol, only its two entry
/// points (software_raster_8.h).

#include "render/easy_font.h"
#include "render/software_raster.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

namespace impulse2d::render {
namespace {

// Window rows per band: each band is one task of the pool, its pixels written by it alone. A
// primitive's setup (colours, `FrameColumns`) is repeated in each band it touches: 32 rows
// rather than 16 take 3 % off the layers' instructions (callgrind, ball_pit 800x600, every
// overlay; 64 would take 2 % more) and still leave 19 bands of a 600-row frame to share out.
constexpr int band_rows = 32;

// A premultiplied colour, as a fragment program outputs it: of one pixel (T = float) or of
// neighbouring pixels of a row (T = Float4 or Float8).
template <typename T>
struct Premultiplied {
  T r = 0.0f;
  T g = 0.0f;
  T b = 0.0f;
  T a = 0.0f;
};

// A colour byte as GL normalises it (c / 255), and the reverse conversion of the blended
// value: clamped to 1, then rounded half up without a libm call (as the batches' colour bytes are).
struct ByteScale {
  float value[256];
  ByteScale() {
    for (int i = 0; i < 256; ++i) value[i] = static_cast<float>(i) / 255.0f;
  }
};
const ByteScale byte_scale;

std::uint8_t to_byte(float value) {
  // Blended values are sums of products of non-negative numbers: only rounding takes them
  // past 1.
  return static_cast<std::uint8_t>(std::min(value, 1.0f) * 255.0f + 0.5f);
}

// A straight (not premultiplied) colour, channels 0..1.
struct Rgba {
  float r, g, b, a;
};

Rgba normalised(const std::uint8_t (&color)[4]) {
  return Rgba{byte_scale.value[color[0]], byte_scale.value[color[1]], byte_scale.value[color[2]],
              byte_scale.value[color[3]]};
}

// The formulas below serve one pixel (float) and several (Float4, Float8) alike: `std::min`,
// `std::max` and `std::abs` for floats, float4.h's and float8.h's for lanes (found by
// argument-dependent lookup).
using std::abs;
using std::max;
using std::min;
using std::sqrt;

template <typename T>
T saturate(T value) {
  return min(max(value, T(0.0f)), T(1.0f));
}

// Coverage of the rectangle with half extents (hx, hy) centred on the origin at p.
template <typename T>
T rectangle(T px, T py, float hx, float hy) {
  return saturate(T(hx + 0.5f) - abs(px)) * saturate(T(hy + 0.5f) - abs(py));
}

// The fill under the line (a ring or outline), premultiplied: both alphas already include coverage.
template <typename T>
Premultiplied<T> fill_under_line(const Rgba& fill, T fill_alpha, const Rgba& line, T line_alpha) {
  const T under = fill_alpha * (T(1.0f) - line_alpha);
  return Premultiplied<T>{T(line.r) * line_alpha + T(fill.r) * under, T(line.g) * line_alpha + T(fill.g) * under,
                          T(line.b) * line_alpha + T(fill.b) * under, line_alpha + under};
}

// `color` over `coverage` of the pixel, premultiplied.
template <typename T>
Premultiplied<T> premultiplied(const Rgba& color, T coverage) {
  const T alpha = T(color.a) * coverage;
  return Premultiplied<T>{T(color.r) * alpha, T(color.g) * alpha, T(color.b) * alpha, alpha};
}

// Whether the pixel centre p lies in triangle (a, b, c): inside all three edges, or on an
// edge that the triangle owns (one pointing up, or left when flat, once counter-clockwise),
// so that two triangles sharing an edge never both cover a pixel centre on it.
bool inside_triangle(vec2 a, vec2 b, vec2 c, vec2 p) {
  const float area = cross(b - a, c - a);
  if (!(area != 0.0f)) return false;
  const float orientation = area > 0.0f ? 1.0f : -1.0f;
  const vec2 corners[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const vec2 edge = orientation * (corners[(i + 1) % 3] - corners[i]);
    const float side = orientation * cross(corners[(i + 1) % 3] - corners[i], p - corners[i]);
    if (side < 0.0f) return false;
    if (side == 0.0f && !(edge.y > 0.0f || (edge.y == 0.0f && edge.x < 0.0f))) return false;
  }
  return true;
}

// How far beyond a primitive's frame rectangle, in pixels, rows are still scanned: the
// spans below are computed differently from the coverage, so they are widened (and a box
// outline's hole narrowed) a little rather than trusted to the last bit.
constexpr float span_slack = 0.05f;

// Up to two runs of columns of one row: [first[i], last[i]] for i < count.
struct RowSpans {
  int first[2] = {0, 0};
  int last[2] = {-1, -1};
  int count = 0;
};

// The pixel columns whose centres lie in [from, to], within [left, right]. Rounds with
// integer conversions (the bounds are first brought within a column of [left, right]). Always
// inlined: it runs on every row of a disc, segment or arrow.
inline __attribute__((always_inline)) RowSpans columns_between(float from, float to, int left, int right) {
  RowSpans spans;
  if (!(from <= to)) return spans;
  // Column c's centre c + 0.5 lies in [from, to] when from - 0.5 <= c <= to - 0.5.
  const float low = std::min(std::max(from - 0.5f, static_cast<float>(left) - 1.0f), static_cast<float>(right) + 1.0f);
  const float high = std::min(std::max(to - 0.5f, static_cast<float>(left) - 1.0f), static_cast<float>(right) + 1.0f);
  int first = static_cast<int>(low);  // truncation: the ceiling for negative values, else below it
  if (static_cast<float>(first) < low) ++first;
  int last = static_cast<int>(high);  // the floor for non-negative values, else above it
  if (static_cast<float>(last) > high) --last;
  first = std::max(first, left);
  last = std::min(last, right);
  if (first <= last) {
    spans.first[0] = first;
    spans.last[0] = last;
    spans.count = 1;
  }
  return spans;
}

// Where slope_x x + slope_y y + offset, a linear function of the pixel centre, lies in
// [low, high] along the row at y: an x range whose ends are linear in y, or, when it
// (nearly) does not depend on x, a test of the row alone.
struct RowLimit {
  bool along_row = false;  // the ends below apply; else the row test
  float from_base = 0.0f;  // x from = from_base + from_slope y
  float from_slope = 0.0f;
  float to_base = 0.0f;    // x to = to_base + to_slope y
  float to_slope = 0.0f;
  float slope_y = 0.0f;    // the row test: low <= slope_y y + offset <= high
  float offset = 0.0f;
  float low = 0.0f;
  float high = 0.0f;
};

// The `RowLimit` of low <= slope_x x + slope_y y + offset <= high.
RowLimit row_limit(float slope_x, float slope_y, float offset, float low, float high) {
  RowLimit limit;
  limit.slope_y = slope_y;
  limit.offset = offset;
  limit.low = low - span_slack;
  limit.high = high + span_slack;
  if (std::abs(slope_x) > 1.0e-6f) {
    limit.along_row = true;
    const float entry = slope_x > 0.0f ? low : high;
    const float exit = slope_x > 0.0f ? high : low;
    limit.from_base = (entry - offset) / slope_x;
    limit.from_slope = -slope_y / slope_x;
    limit.to_base = (exit - offset) / slope_x;
    limit.to_slope = -slope_y / slope_x;
  }
  return limit;
}

// Whether the row at y passes the row test of a `limit` that is not `along_row`.
bool row_passes(const RowLimit& limit, float y) {
  const float value = limit.slope_y * y + limit.offset;
  return !(value < limit.low || value > limit.high);
}

// Narrows [from, to] to the x that `limit` allows on the row at y.
void apply(const RowLimit& limit, float y, float& from, float& to) {
  if (limit.along_row) {
    from = std::max(from, limit.from_base + limit.from_slope * y);
    to = std::min(to, limit.to_base + limit.to_slope * y);
  } else if (!row_passes(limit, y)) {  // empty, and stays so
    from = std::numeric_limits<float>::max();
    to = std::numeric_limits<float>::lowest();
  }
}

// Whether `limit` bounds x alike on every row (an axis-aligned frame's x limit): its ends do
// not move with y, so `apply` gives them exactly (x + 0 y = x).
bool same_every_row(const RowLimit& limit) {
  return limit.along_row && limit.from_slope == 0.0f && limit.to_slope == 0.0f;
}

// The columns of the one span `spans` left and right of the hole's [hole_from, hole_to].
RowSpans beside_hole(const RowSpans& spans, float hole_from, float hole_to) {
  const RowSpans inside = columns_between(hole_from, hole_to, spans.first[0], spans.last[0]);
  if (inside.count == 0) return spans;
  RowSpans sides;
  if (inside.first[0] > spans.first[0]) {
    sides.first[sides.count] = spans.first[0];
    sides.last[sides.count++] = inside.first[0] - 1;
  }
  if (inside.last[0] < spans.last[0]) {
    sides.first[sides.count] = inside.last[0] + 1;
    sides.last[sides.count++] = spans.last[0];
  }
  return sides;
}

// The columns of each row that a disc, box or arrow may cover: its frame rectangle
// [lower, upper] (p.x = ax x + ay y - (ax ox + ay oy), p.y = -ay x + ax y + (ay ox - ax oy)),
// without a box outline's hole (where its coverage is exactly 1 - 1 = 0). In an axis-aligned
// frame (bounding boxes, panels) the columns are the same on every row the rectangle (or the
// hole) spans, so they are found once and each row only tests y.
class FrameColumns {
 public:
  FrameColumns(const SoftwarePrimitive& primitive, const ShapeVertex& shape, bool outline)
      : left_(primitive.left), right_(primitive.right) {
    limits(shape, primitive.frame_lower, primitive.frame_upper, outer_);
    const vec2 hole(shape.box[0] - shape.box[3] - 0.5f - 2.0f * span_slack,
                    shape.box[1] - shape.box[3] - 0.5f - 2.0f * span_slack);
    has_hole_ = outline && hole.x > 0.0f && hole.y > 0.0f;
    if (has_hole_) limits(shape, -hole, hole, hole_);
    fixed_ = same_every_row(outer_[0]) && !outer_[1].along_row &&
             (!has_hole_ || (same_every_row(hole_[0]) && !hole_[1].along_row));
    if (!fixed_) return;
    // What `operator()` computes on a row inside the rectangle, outside and inside the hole.
    fixed_spans_ = columns_between(std::max(std::numeric_limits<float>::lowest(), outer_[0].from_base) - span_slack,
                                   std::min(std::numeric_limits<float>::max(), outer_[0].to_base) + span_slack, left_,
                                   right_);
    fixed_sides_ = fixed_spans_;
    if (has_hole_ && fixed_spans_.count != 0) {
      fixed_sides_ = beside_hole(fixed_spans_, std::max(std::numeric_limits<float>::lowest(), hole_[0].from_base),
                                 std::min(std::numeric_limits<float>::max(), hole_[0].to_base));
    }
  }

  // The columns of the row at y when they are the same on every row that is not empty (always
  // in an axis-aligned frame); else none.
  const RowSpans& fixed_row(float y) const {
    static const RowSpans none;
    if (!row_passes(outer_[1], y)) return none;
    return has_hole_ && row_passes(hole_[1], y) ? fixed_sides_ : fixed_spans_;
  }

  RowSpans operator()(float y) const {
    if (fixed_) return fixed_row(y);
    float from = std::numeric_limits<float>::lowest();
    float to = std::numeric_limits<float>::max();
    apply(outer_[0], y, from, to);
    apply(outer_[1], y, from, to);
    const RowSpans spans = columns_between(from - span_slack, to + span_slack, left_, right_);
    if (!has_hole_ || spans.count == 0) return spans;
    float hole_from = std::numeric_limits<float>::lowest();
    float hole_to = std::numeric_limits<float>::max();
    apply(hole_[0], y, hole_from, hole_to);
    apply(hole_[1], y, hole_from, hole_to);
    return beside_hole(spans, hole_from, hole_to);
  }

 private:
  static void limits(const ShapeVertex& shape, vec2 lower, vec2 upper, RowLimit (&out)[2]) {
    const float ax = shape.frame[2];
    const float ay = shape.frame[3];
    const float ox = shape.frame[0];
    const float oy = shape.frame[1];
    out[0] = row_limit(ax, ay, -(ax * ox + ay * oy), lower.x, upper.x);
    out[1] = row_limit(-ay, ax, ay * ox - ax * oy, lower.y, upper.y);
  }

  int left_;
  int right_;
  RowLimit outer_[2];
  RowLimit hole_[2];
  bool has_hole_ = false;
  bool fixed_ = false;     // the columns are `fixed_spans_` / `fixed_sides_` on rows that pass
  RowSpans fixed_spans_;   // on a row inside the rectangle and outside the hole
  RowSpans fixed_sides_;   // on a row inside the hole
};

// The columns of row centre `y` within the disc's reach (`frame_upper.x`) of its centre.
RowSpans disc_columns(const SoftwarePrimitive& primitive, const ShapeVertex& shape, float y) {
  const float reach = primitive.frame_upper.x + span_slack;
  const float dy = y - shape.frame[1];
  const float squared = reach * reach - dy * dy;
  if (!(squared > 0.0f)) return RowSpans{};
  const float half_width = std::sqrt(squared);
  return columns_between(shape.frame[0] - half_width, shape.frame[0] + half_width, primitive.left, primitive.right);
}

// Blends the premultiplied `source` over the opaque `pixel`; a pixel with nothing over it keeps
// its bytes.
void blend_pixel(std::uint8_t* pixel, const Premultiplied<float>& source) {
  if (!(source.a > 0.0f)) return;
  // Alpha blends as source.a + 1 (1 - source.a) = 1 over an opaque frame: it stays 255.
  const float keep = 1.0f - source.a;
  pixel[0] = to_byte(source.r + byte_scale.value[pixel[0]] * keep);
  pixel[1] = to_byte(source.g + byte_scale.value[pixel[1]] * keep);
  pixel[2] = to_byte(source.b + byte_scale.value[pixel[2]] * keep);
}

// Blends `shade(x, y)` (a premultiplied colour at the window pixel centre) over the pixels
// of `primitive` in window rows [first_row, last_row], in each row those `columns(y)` gives.
template <typename Columns, typename Shade>
void blend(const SoftwarePrimitive& primitive, int first_row, int last_row, Frame& frame, const Columns& columns,
           const Shade& shade) {
  const std::size_t stride = frame.stride();
  for (int row = std::max(primitive.bottom, first_row); row <= std::min(primitive.top, last_row); ++row) {
    const float y = static_cast<float>(row) + 0.5f;
    const RowSpans spans = columns(y);
    // GL's rows count from the bottom; the frame's from the top.
    std::uint8_t* const row_pixels = frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
    for (int span = 0; span < spans.count; ++span) {
      std::uint8_t* pixel = row_pixels + static_cast<std::size_t>(spans.first[span]) * 4;
      for (int column = spans.first[span]; column <= spans.last[span]; ++column, pixel += 4) {
        blend_pixel(pixel, shade(static_cast<float>(column) + 0.5f, y));
      }
    }
  }
}

// A colour channel of premultiplied `value` over the pixel's `byte` with `keep` = 1 - alpha, as
// `blend_pixel` computes it before the conversion: (value + byte / 255 keep), at most 1, times
// 255, plus a half (truncated on store: rounded half up).
template <typename F>
inline __attribute__((always_inline)) F blended_channel(F value, F byte, F keep) {
  return min(value + byte / F(255.0f) * keep, F(1.0f)) * F(255.0f) + F(0.5f);
}

// Blends `source` (the premultiplied colours of F::width pixels) over the opaque pixels at
// `target`, as `blend` does one pixel at a time (`blended_channel`); alpha stays; pixels with
// nothing over them (`alpha` not above 0) keep their bytes, and a group of such pixels (an
// arrow's frame beside its shaft) is not read at all. Always inlined: a call passes `source`
// through memory (7 % more instructions in the layers).
template <typename F>
inline __attribute__((always_inline)) void blend_group(std::uint8_t* target, const Premultiplied<F>& source, F alpha) {
  if (!any_positive(alpha)) return;
  const typename F::Pixels old = F::Pixels::load(target);
  const F keep = F(1.0f) - source.a;
  old.store(target, blended_channel(source.r, old.r, keep), blended_channel(source.g, old.g, keep),
            blended_channel(source.b, old.b, keep), alpha);
}

// `blend_group` of four pixels at `low` (lanes 0..3) and four at `high` (lanes 4..7), which must
// not overlap; eight lanes only.
template <typename F>
inline __attribute__((always_inline)) void blend_group_halves(std::uint8_t* low, std::uint8_t* high,
                                                              const Premultiplied<F>& source, F alpha) {
  if constexpr (F::width == 8) {
    if (!any_positive(alpha)) return;
    const typename F::Pixels old = F::Pixels::load_halves(low, high);
    const F keep = F(1.0f) - source.a;
    old.store_halves(low, high, blended_channel(source.r, old.r, keep), blended_channel(source.g, old.g, keep),
                     blended_channel(source.b, old.b, keep), alpha);
  }
}

// A span of at most four pixels of a row, waiting to share a group of eight lanes with another.
struct ThinSpan {
  std::uint8_t* row_pixels = nullptr;  // its row of the frame
  int first = 0;                       // its columns: [first, last]
  int last = -1;
  float y = 0.0f;                      // the row's pixel centre
};

// Whether the pixels [first, last] of a row of a frame `width` pixels wide are a `ThinSpan` that
// shares a group (only with eight lanes): at most four, and the four from `first` inside the row.
template <typename F>
bool is_thin(int first, int last, int width) {
  return F::width == 8 && last - first < 4 && first + 4 <= width;
}

// Whether the thin spans `low` and `high` can be drawn as one group: four pixels from each first
// column, which must not overlap (they may be of one row).
inline bool may_pair(const ThinSpan& low, const ThinSpan& high) {
  return low.row_pixels != high.row_pixels || low.first + 4 <= high.first || high.first + 4 <= low.first;
}

// Blends `shade(x, y)` over the pixels of two thin spans at once, `low` in lanes 0..3 and `high`
// in lanes 4..7 (each lane with its own pixel centre, so each pixel gets the bytes `blend_span`
// gives it); eight lanes only.
template <typename F, typename Shade>
inline __attribute__((always_inline)) void blend_pair(const ThinSpan& low, const ThinSpan& high, const Shade& shade) {
  if constexpr (F::width == 8) {
    const Premultiplied<F> source = shade(F::ramp_halves(static_cast<float>(low.first) + 0.5f,
                                                         static_cast<float>(high.first) + 0.5f),
                                          F::halves(low.y, high.y));
    blend_group_halves(low.row_pixels + static_cast<std::size_t>(low.first) * 4,
                       high.row_pixels + static_cast<std::size_t>(high.first) * 4, source,
                       source.a * F::first_lanes_halves(low.last - low.first + 1, high.last - high.first + 1));
  }
}

// Blends `source` (the premultiplied colours of F::width pixels) over the fewer than F::width
// pixels [column, last] of a row of a frame `width` pixels wide: the lanes past them leave the
// pixels of the row beyond as they are (this band owns its rows), or near the row's end a copy.
template <typename F>
inline __attribute__((always_inline)) void blend_tail(std::uint8_t* row_pixels, int column, int last, int width,
                                                      const Premultiplied<F>& source) {
  std::uint8_t* const pixel = row_pixels + static_cast<std::size_t>(column) * 4;
  const int count = last - column + 1;
  const F alpha = source.a * F::first_lanes(count);
  if (column + F::width <= width) {
    blend_group(pixel, source, alpha);
    return;
  }
  std::uint8_t spill[4 * F::width] = {};
  std::memcpy(spill, pixel, static_cast<std::size_t>(count) * 4);
  blend_group(spill, source, alpha);
  std::memcpy(pixel, spill, static_cast<std::size_t>(count) * 4);
}

// Blends `shade(column)` (the premultiplied colours of the F::width pixels from `column` on)
// over the pixels [first, last] of a row of a frame `width` pixels wide, F::width at a time.
// Always inlined into the row loop, whose shading constants (colours, radii as lanes) then need
// not be set up again on each row.
template <typename F, typename Shade>
inline __attribute__((always_inline)) void blend_span(std::uint8_t* row_pixels, int first, int last, int width,
                                                      const Shade& shade) {
  int column = first;
  for (; column + F::width - 1 <= last; column += F::width) {  // every lane is written where its alpha is above 0
    const Premultiplied<F> source = shade(column);
    blend_group(row_pixels + static_cast<std::size_t>(column) * 4, source, source.a);
  }
  if (column <= last) blend_tail(row_pixels, column, last, width, shade(column));
}

// Blends `shade(x, y)` (F::width premultiplied colours at the window pixel centres x, the
// centres of neighbouring pixels of the row at y) over the pixels of `primitive` in window rows
// [first_row, last_row], in each row those `columns(y)` gives, `columns = make_columns()` (made
// only when needed): the same bytes as `blend` with the same formulas one pixel at a time.
// With eight lanes, spans of at most four pixels (a long steep line's rows, a large disc's top and
// bottom rows) are drawn two to a group (`blend_pair`), in the order they come; the pixels are
// those of one span at a time, since each lane is shaded at its own pixel centre and the two
// spans' pixels are apart. A mark at most a group wide skips the columns altogether (below).
template <typename F, typename MakeColumns, typename Shade>
void blend_lanes(const SoftwarePrimitive& primitive, int first_row, int last_row, Frame& frame,
                 const MakeColumns& make_columns, const Shade& shade) {
  const std::size_t stride = frame.stride();
  ThinSpan waiting;
  bool is_waiting = false;
  const auto blend_alone = [&](const ThinSpan& span) __attribute__((always_inline)) {
    blend_span<F>(span.row_pixels, span.first, span.last, frame.width,
                  [&](int column) { return shade(F::ramp(static_cast<float>(column) + 0.5f), F(span.y)); });
  };
  if (primitive.right - primitive.left < F::width) {
    // A mark at most a group wide (a dot, a short or steep line, a bar): every row of its bounds
    // is one group (two rows to a group when it is at most four pixels wide), without finding
    // the row's columns. The pixels beyond the columns have coverage 0 (the columns hold every
    // pixel of positive coverage, with a margin), so they keep their bytes, as unvisited.
    const int bottom = std::max(primitive.bottom, first_row);
    const int top = std::min(primitive.top, last_row);
    const auto row_span = [&](int row) {
      return ThinSpan{frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride, primitive.left,
                      primitive.right, static_cast<float>(row) + 0.5f};
    };
    int row = bottom;
    if (is_thin<F>(primitive.left, primitive.right, frame.width)) {
      for (; row < top; row += 2) blend_pair<F>(row_span(row), row_span(row + 1), shade);
    }
    for (; row <= top; ++row) blend_alone(row_span(row));
    return;
  }
  const auto columns = make_columns();
  for (int row = std::max(primitive.bottom, first_row); row <= std::min(primitive.top, last_row); ++row) {
    const float y = static_cast<float>(row) + 0.5f;
    const RowSpans spans = columns(y);
    std::uint8_t* const row_pixels = frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
    for (int span = 0; span < spans.count; ++span) {
      const ThinSpan current{row_pixels, spans.first[span], spans.last[span], y};
      if (!is_thin<F>(current.first, current.last, frame.width)) {
        blend_alone(current);
        continue;
      }
      if (!is_waiting) {
        waiting = current;
        is_waiting = true;
        continue;
      }
      if (may_pair(waiting, current)) {
        blend_pair<F>(waiting, current, shade);
        is_waiting = false;
      } else {
        blend_alone(waiting);
        waiting = current;
      }
    }
  }
  if (is_waiting) blend_alone(waiting);
}

// Blends `shade(px, py)` of F::width pixel centres p in the shape's frame (origin and unit x
// axis), F::width at a time (`blend_lanes`); for the axis-aligned frame (axis (1, 0): discs,
// bounding boxes, panels) p is exactly (x - ox, y - oy), computed without the rotation.
template <typename F, typename MakeColumns, typename Shade>
void blend_in_frame(const SoftwarePrimitive& primitive, int first_row, int last_row, Frame& frame,
                    const MakeColumns& make_columns, const ShapeVertex& shape, const Shade& shade) {
  const F origin_x(shape.frame[0]);
  const F origin_y(shape.frame[1]);
  if (shape.frame[2] == 1.0f && shape.frame[3] == 0.0f) {
    blend_lanes<F>(primitive, first_row, last_row, frame, make_columns,
                   [=](F x, F y) { return shade(x - origin_x, y - origin_y); });
    return;
  }
  const F axis_x(shape.frame[2]);
  const F axis_y(shape.frame[3]);
  blend_lanes<F>(primitive, first_row, last_row, frame, make_columns, [=](F x, F y) {
    const F dx = x - origin_x;
    const F dy = y - origin_y;
    return shade(dx * axis_x + dy * axis_y, axis_x * dy - axis_y * dx);
  });
}

// An axis-aligned box (bounding boxes, panels, the highlight) in window rows [first_row,
// last_row]: its coverage is a column factor times a row factor of `rectangle` (an outline's
// less the hole's), each computed as there (the same bytes), so each row's factors are found
// once and each F::width columns' once for all the rows that share the columns' spans. The
// columns are the bounds'; on an outline's rows whose inner row factor is exactly 1 (so is the
// outer one), only those beside the hole: inside it the inner column factor is 1 for sure, and so
// the coverage is 1 x 1 - 1 x 1 = 0. On those rows a column's coverage does not depend on the
// row (a product with 1 is exact), so a group's colour is found once for all of them.
template <typename F>
void draw_axis_box(const SoftwarePrimitive& primitive, const ShapeVertex& shape, int first_row, int last_row,
                   Frame& frame) {
  const int bottom = std::max(primitive.bottom, first_row);
  const int top = std::min(primitive.top, last_row);
  if (bottom > top) return;
  const bool outline = shape.box[3] > 0.0f;
  const Rgba fill = normalised(shape.fill);
  const float outer_x = shape.box[0] + 0.5f;
  const float outer_y = shape.box[1] + 0.5f;
  const float inner_x = (shape.box[0] - shape.box[3]) + 0.5f;
  const float inner_y = (shape.box[1] - shape.box[3]) + 0.5f;
  // Set 0: every column of the bounds; set 1 (an outline's rows inside the hole): beside it.
  RowSpans spans[2];
  spans[0].first[0] = primitive.left;
  spans[0].last[0] = primitive.right;
  spans[0].count = 1;
  spans[1] = spans[0];
  // |px| <= inner_x - 1 gives an inner column factor of 1; the slack covers px's rounding.
  const float hole = inner_x - 1.0f - span_slack;
  if (outline && hole > 0.0f) spans[1] = beside_hole(spans[0], shape.frame[0] - hole, shape.frame[0] + hole);
  int set_rows[2][band_rows];
  int set_row_count[2] = {0, 0};
  float outer_row[band_rows];
  float inner_row[band_rows];
  for (int row = bottom; row <= top; ++row) {
    const float py = (static_cast<float>(row) + 0.5f) - shape.frame[1];
    const int i = row - bottom;
    outer_row[i] = saturate(outer_y - std::abs(py));
    inner_row[i] = saturate(inner_y - std::abs(py));
    if (!(outer_row[i] > 0.0f)) continue;  // coverage 0 (the inner factor is at most the outer)
    const int set = outline && inner_row[i] == 1.0f ? 1 : 0;
    set_rows[set][set_row_count[set]++] = row;
  }
  const F origin_x(shape.frame[0]);
  const std::size_t stride = frame.stride();
  // The coverage of the columns `outer_column`, `inner_column` on the rows of `set`, at `i`.
  const auto coverage_at = [&](int set, F outer_column, F inner_column, int i) {
    if (set == 1) return outer_column * F(1.0f) - inner_column * F(1.0f);
    F coverage = outer_column * F(outer_row[i]);
    if (outline) coverage = coverage - inner_column * F(inner_row[i]);
    return coverage;
  };
  for (int set = 0; set < 2; ++set) {
    const RowSpans& set_spans = spans[set];
    if (set_row_count[set] == 0) continue;
    if constexpr (F::width == 8) {
      // An outline's sides beside the hole, each at most four pixels wide: both in one group.
      if (set_spans.count == 2 && is_thin<F>(set_spans.first[0], set_spans.last[0], frame.width) &&
          is_thin<F>(set_spans.first[1], set_spans.last[1], frame.width) && set_spans.first[0] + 4 <= set_spans.first[1]) {
        const F px = F::ramp_halves(static_cast<float>(set_spans.first[0]) + 0.5f,
                                    static_cast<float>(set_spans.first[1]) + 0.5f) -
                     origin_x;
        const F outer_column = saturate(F(outer_x) - abs(px));
        const F inner_column = saturate(F(inner_x) - abs(px));
        const F lanes =
            F::first_lanes_halves(set_spans.last[0] - set_spans.first[0] + 1, set_spans.last[1] - set_spans.first[1] + 1);
        const Premultiplied<F> same = premultiplied(fill, coverage_at(1, outer_column, inner_column, 0));
        for (int k = 0; k < set_row_count[set]; ++k) {
          const int row = set_rows[set][k];
          std::uint8_t* const row_pixels = frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
          const Premultiplied<F> source =
              set == 1 ? same : premultiplied(fill, coverage_at(set, outer_column, inner_column, row - bottom));
          blend_group_halves(row_pixels + static_cast<std::size_t>(set_spans.first[0]) * 4,
                             row_pixels + static_cast<std::size_t>(set_spans.first[1]) * 4, source, source.a * lanes);
        }
        continue;
      }
    }
    for (int span = 0; span < set_spans.count; ++span) {
      for (int column = set_spans.first[span]; column <= set_spans.last[span]; column += F::width) {
        const F px = F::ramp(static_cast<float>(column) + 0.5f) - origin_x;
        const F outer_column = saturate(F(outer_x) - abs(px));
        const F inner_column = saturate(F(inner_x) - abs(px));
        const Premultiplied<F> same = premultiplied(fill, coverage_at(1, outer_column, inner_column, 0));
        for (int k = 0; k < set_row_count[set]; ++k) {
          const int row = set_rows[set][k];
          std::uint8_t* const row_pixels =
              frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
          const Premultiplied<F> source =
              set == 1 ? same : premultiplied(fill, coverage_at(set, outer_column, inner_column, row - bottom));
          if (column + F::width - 1 <= set_spans.last[span]) {
            blend_group(row_pixels + static_cast<std::size_t>(column) * 4, source, source.a);
          } else {
            blend_tail(row_pixels, column, set_spans.last[span], frame.width, source);
          }
        }
      }
    }
  }
}

// Whether a text run's corner and size are whole pixels, as labels and the HUD place them:
// then its coverage at every pixel centre is exactly 0 or 1 (`draw_text_run`'s factors are
// saturate(k + 0.5 + 0.5) for integers k, and ink is 0 or 1).
bool in_whole_pixels(const TextVertex& run) {
  // A conversion to int truncates, which gives back a value within 2^23 exactly when it is whole
  // (no libm call here: see the file comment on linkage).
  for (const float value : run.run) {
    if (!(std::abs(value) < 8388608.0f) || static_cast<float>(static_cast<int>(value)) != value) return false;
  }
  return true;
}

// `draw_text_run` of an opaque run in whole pixels: each pixel with ink inside the run gets the
// colour `blended_channel` gives for coverage 1 and alpha 1 (min(c + byte / 255 * 0, 1) * 255
// + 0.5, which is `to_byte(c)`: the same bytes), written without blending; the margin's pixels
// (coverage 0) are not visited.
template <typename F>
void draw_opaque_text_run(const SoftwarePrimitive& primitive, const TextVertex& run, int first_row, int last_row,
                          Frame& frame) {
  const Rgba fill = normalised(run.fill);
  const std::uint32_t rgb = static_cast<std::uint32_t>(to_byte(fill.r)) |
                            static_cast<std::uint32_t>(to_byte(fill.g)) << 8 |
                            static_cast<std::uint32_t>(to_byte(fill.b)) << 16;
  // The pixels whose centres lie inside the run (a factor of 1): columns run[0] ..
  // run[0] + run[2] - 1 and rows run[1] - run[3] .. run[1] - 1.
  const RowSpans columns =
      columns_between(run.run[0] + 0.5f, run.run[0] + run.run[2] - 0.5f, primitive.left, primitive.right);
  const RowSpans rows = columns_between(run.run[1] - run.run[3] + 0.5f, run.run[1] - 0.5f,
                                        std::max(primitive.bottom, first_row), std::min(primitive.top, last_row));
  if (columns.count == 0 || rows.count == 0) return;
  const std::size_t stride = frame.stride();
  constexpr int chunk = 64;  // pixel columns whose font columns are held at once
  std::int32_t bit_columns[chunk + F::width] = {};
  for (int first_column = columns.first[0]; first_column <= columns.last[0]; first_column += chunk) {
    const int last_column = std::min(first_column + chunk - 1, columns.last[0]);
    for (int column = first_column; column <= last_column; ++column) {
      const float qx = static_cast<float>(column) + 0.5f - run.run[0];
      bit_columns[column - first_column] = std::min(static_cast<int>(qx * run.font_scale), 31) * font_glyph_rows;
    }
    for (int row = rows.first[0]; row <= rows.last[0]; ++row) {
      const float qy = run.run[1] - (static_cast<float>(row) + 0.5f);
      const int font_row = std::min(static_cast<int>(qy * run.font_scale), font_glyph_rows - 1);
      std::uint8_t* const row_pixels = frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
      for (int column = first_column; column <= last_column; column += F::width) {
        F ink = F::bits(run.bits, bit_columns + (column - first_column), font_row);
        if (!any_positive(ink)) continue;
        std::uint8_t* const pixel = row_pixels + static_cast<std::size_t>(column) * 4;
        if (column + F::width - 1 <= last_column) {
          F::Pixels::paint(pixel, ink, rgb);
          continue;
        }
        // The last group: lanes past the run's columns are not painted; near the row's end a copy.
        const int count = last_column - column + 1;
        ink = ink * F::first_lanes(count);
        if (column + F::width <= frame.width) {
          F::Pixels::paint(pixel, ink, rgb);
          continue;
        }
        std::uint8_t spill[4 * F::width] = {};
        std::memcpy(spill, pixel, static_cast<std::size_t>(count) * 4);
        F::Pixels::paint(spill, ink, rgb);
        std::memcpy(pixel, spill, static_cast<std::size_t>(count) * 4);
      }
    }
  }
}

// A text run in window rows [first_row, last_row]: ink where the font pixel under the pixel
// centre is set, within the run (the text fragment program's formula), F::width pixels at a time.
// The font column under each pixel column is found once per call and the font row once per row,
// with the same conversions as pixel by pixel, so pixels without ink cost a bit test each
// (F::bits), and a group of them nothing more.
template <typename F>
void draw_text_run(const SoftwarePrimitive& primitive, const TextVertex& run, int first_row, int last_row,
                   Frame& frame) {
  const Rgba fill = normalised(run.fill);
  if (fill.a == 1.0f && in_whole_pixels(run)) {
    draw_opaque_text_run<F>(primitive, run, first_row, last_row, frame);
    return;
  }
  const std::size_t stride = frame.stride();
  const int bottom = std::max(primitive.bottom, first_row);
  const int top = std::min(primitive.top, last_row);
  constexpr int chunk = 64;  // pixel columns whose font columns are held at once
  // Font column times font_glyph_rows, the column's first bit; the lanes past a chunk's last
  // column read what is there and are not drawn.
  std::int32_t bit_columns[chunk + F::width] = {};
  for (int first_column = primitive.left; first_column <= primitive.right; first_column += chunk) {
    const int last_column = std::min(first_column + chunk - 1, primitive.right);
    for (int column = first_column; column <= last_column; ++column) {
      // The pixel centre from the run's left edge, and the font column under it. (The pixel
      // lies within a pixel of the run, so the conversions are in range.)
      const float qx = static_cast<float>(column) + 0.5f - run.run[0];
      bit_columns[column - first_column] = std::min(static_cast<int>(qx * run.font_scale), 31) * font_glyph_rows;
    }
    for (int row = bottom; row <= top; ++row) {
      // The pixel centre below the run's top (y down), the font row under it, and the row's
      // factor of the coverage.
      const float qy = run.run[1] - (static_cast<float>(row) + 0.5f);
      const float row_coverage = saturate(std::min(qy, run.run[3] - qy) + 0.5f);
      // The run's margin rows (half a pixel beyond its top and bottom): coverage 0 everywhere.
      if (!(row_coverage > 0.0f)) continue;
      const int font_row = std::min(static_cast<int>(qy * run.font_scale), font_glyph_rows - 1);
      const F inside_row(row_coverage);
      // GL's rows count from the bottom; the frame's from the top.
      std::uint8_t* const row_pixels = frame.rgba.data() + static_cast<std::size_t>(frame.height - 1 - row) * stride;
      for (int column = first_column; column <= last_column; column += F::width) {
        const F ink = F::bits(run.bits, bit_columns + (column - first_column), font_row);
        if (!any_positive(ink)) continue;
        const F qx = F::ramp(static_cast<float>(column) + 0.5f) - F(run.run[0]);
        const F inside = saturate(min(qx, F(run.run[2]) - qx) + F(0.5f)) * inside_row;
        // Where there is ink, inside times 1 is inside: the coverage pixel by pixel.
        const Premultiplied<F> source = premultiplied(fill, inside * ink);
        if (column + F::width - 1 <= last_column) {
          blend_group(row_pixels + static_cast<std::size_t>(column) * 4, source, source.a);
        } else {
          blend_tail(row_pixels, column, last_column, frame.width, source);
        }
      }
    }
  }
}

// The coverage formulas of primitive_shaders.cpp, kind by kind; discs, boxes, arrows and text
// runs F::width pixels at a time.
template <typename F>
void draw_primitive(const SoftwareBatch& batch, const SoftwarePrimitive& primitive, int first_row, int last_row,
                    Frame& frame) {
  const auto whole_rows = [&](float) { return columns_between(-1.0e30f, 1.0e30f, primitive.left, primitive.right); };
  switch (primitive.kind) {
    case PrimitiveKind::polygon: {
      const PolygonVertex shape = batch.polygons[primitive.index];
      const Rgba fill = normalised(shape.fill);
      const Rgba line = normalised(shape.line);
      blend(primitive, first_row, last_row, frame, whole_rows, [=](float x, float y) {
        const float px = x - shape.origin[0];
        const float py = y - shape.origin[1];
        float distance = shape.edges[0][0] * px + shape.edges[0][1] * py - shape.edges[0][2];
        for (int i = 1; i < polygon_primitive_edges; ++i) {
          distance = std::max(distance, shape.edges[i][0] * px + shape.edges[i][1] * py - shape.edges[i][2]);
        }
        const float fill_alpha = fill.a * saturate(0.5f - distance);
        const float line_alpha = line.a * saturate(shape.origin[2] + 0.5f - std::abs(distance));
        return fill_under_line(fill, fill_alpha, line, line_alpha);
      });
      return;
    }
    case PrimitiveKind::solid: {
      const FillQuad quad = batch.fill_quads[primitive.index];
      const Rgba fill = normalised(quad.fill);
      const Premultiplied<float> color = premultiplied(fill, 1.0f);
      blend(primitive, first_row, last_row, frame, whole_rows, [=](float x, float y) {
        const vec2 p(x, y);
        const bool inside = inside_triangle(quad.corners[0], quad.corners[1], quad.corners[2], p) ||
                            inside_triangle(quad.corners[0], quad.corners[2], quad.corners[3], p);
        return inside ? color : Premultiplied<float>{};
      });
      return;
    }
    case PrimitiveKind::disc: {
      const ShapeVertex shape = batch.shapes[primitive.index];
      const Rgba fill = normalised(shape.fill);
      const Rgba line = normalised(shape.line);
      const auto make_columns = [&] { return [&](float y) { return disc_columns(primitive, shape, y); }; };
      // A dot (no ring) or a ring alone: with the other colour's alpha 0, `fill_under_line` is
      // `premultiplied` of the one colour, bit for bit (x * 1, x + 0 and 0 * y are exact for the
      // finite, non-negative values here), so the other's coverage is not computed.
      if (line.a == 0.0f) {
        blend_in_frame<F>(primitive, first_row, last_row, frame, make_columns, shape, [=](F px, F py) {
          const F r = sqrt(px * px + py * py);
          return premultiplied(fill, saturate(F(shape.disc[0] + 0.5f) - r));
        });
        return;
      }
      if (fill.a == 0.0f) {
        blend_in_frame<F>(primitive, first_row, last_row, frame, make_columns, shape, [=](F px, F py) {
          const F r = sqrt(px * px + py * py);
          return premultiplied(line, saturate(F(shape.disc[1] + 0.5f) - r) * saturate(r - shape.disc[2] + 0.5f));
        });
        return;
      }
      blend_in_frame<F>(primitive, first_row, last_row, frame, make_columns, shape, [=](F px, F py) {
        const F r = sqrt(px * px + py * py);
        const F disc = saturate(F(shape.disc[0] + 0.5f) - r);
        const F ring = saturate(F(shape.disc[1] + 0.5f) - r) * saturate(r - shape.disc[2] + 0.5f);
        return fill_under_line(fill, fill.a * disc, line, line.a * ring);
      });
      return;
    }
    case PrimitiveKind::box: {
      const ShapeVertex shape = batch.shapes[primitive.index];
      if (shape.frame[2] == 1.0f && shape.frame[3] == 0.0f) {
        draw_axis_box<F>(primitive, shape, first_row, last_row, frame);
        return;
      }
      const Rgba fill = normalised(shape.fill);
      blend_in_frame<F>(primitive, first_row, last_row, frame,
                        [&] { return FrameColumns(primitive, shape, shape.box[3] > 0.0f); }, shape, [=](F px, F py) {
                          F coverage = rectangle(px, py, shape.box[0], shape.box[1]);
                          if (shape.box[3] > 0.0f) {
                            coverage = coverage -
                                       rectangle(px, py, shape.box[0] - shape.box[3], shape.box[1] - shape.box[3]);
                          }
                          return premultiplied(fill, coverage);
                        });
      return;
    }
    case PrimitiveKind::arrow: {
      const ShapeVertex shape = batch.shapes[primitive.index];
      const Rgba fill = normalised(shape.fill);
      blend_in_frame<F>(primitive, first_row, last_row, frame, [&] { return FrameColumns(primitive, shape, false); },
                        shape, [=](F px, F py) {
                          const F side = (px - shape.head[1]) * shape.head[2] + abs(py) * shape.head[3];
                          const F head = saturate(F(0.5f) - max(max(shape.head[0] - px, px - shape.head[1]), side));
                          return premultiplied(fill, max(rectangle(px, py, shape.box[0], shape.box[1]), head));
                        });
      return;
    }
    case PrimitiveKind::text:
      draw_text_run<F>(primitive, batch.texts[primitive.index], first_row, last_row, frame);
      return;
  }
}

// Draws the primitives `band` (indices into `batch.primitives`, in drawing order) in window
// rows [first_row, last_row].
template <typename F>
void draw_band(const SoftwareBatch& batch, const std::vector<std::uint32_t>& band, int first_row, int last_row,
               Frame& frame) {
  for (const std::uint32_t i : band) draw_primitive<F>(batch, batch.primitives[i], first_row, last_row, frame);
}

}  // namespace
}  // namespace impulse2d::render

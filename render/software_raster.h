#pragma once
/// @file software_raster.h
/// The CPU rasteriser of the overlay layers: primitives with the parameters the fragment
/// programs read (primitive_vertices.h), their coverage computed by the same formulas at
/// each pixel centre and blended premultiplied "over" (GL's ONE, ONE_MINUS_SRC_ALPHA) into
/// a frame already read back from GL. llvmpipe pays thousands of instructions per primitive
/// and hundreds per 4x4 block it touches; here a primitive costs its pixels.

#include "core/math.h"
#include "render/frame.h"
#include "render/primitive_vertices.h"
#include "render/thread_pool.h"

#include <cstdint>
#include <vector>

namespace impulse2d::render {

/// One primitive of a CPU layer: its kind, its parameters' index in the `SoftwareBatch`
/// array of that kind, and the window pixels it may touch (columns `left`..`right` and rows
/// `bottom`..`top`, inclusive, rows counted from the bottom as in GL, inside the frame).
struct SoftwarePrimitive {
  PrimitiveKind kind = PrimitiveKind::box;  ///< which coverage formula
  std::uint32_t index = 0;                  ///< into the array of the kind's parameters
  int left = 0;                             ///< first column
  int bottom = 0;                           ///< first row from the bottom
  int right = -1;                           ///< last column
  int top = -1;                             ///< last row from the bottom
  /// Disc, box and arrow kinds: the rectangle of the primitive's own frame (`ShapeVertex::frame`)
  /// outside which its coverage is 0, so rows are scanned only where it lies. It must hold every
  /// pixel of positive coverage: a mark at most a group of lanes wide is drawn over its whole
  /// bounds, and the pixels outside this rectangle keep their bytes only because they get none.
  vec2 frame_lower = vec2(-1.0e30f);
  vec2 frame_upper = vec2(1.0e30f);  ///< see `frame_lower`
};

/// Two triangles (0, 1, 2) and (0, 2, 3) of a polygon's fill, window pixels, coverage 1
/// (`PrimitiveKind::solid`).
struct FillQuad {
  vec2 corners[4];  ///< window pixels, y up
  std::uint8_t fill[4] = {0, 0, 0, 0};  ///< colour
};

/// The primitives of the CPU layers of a frame, in drawing order, with their parameters.
struct SoftwareBatch {
  std::vector<SoftwarePrimitive> primitives;  ///< drawing order
  std::vector<ShapeVertex> shapes;            ///< discs, boxes and arrows
  std::vector<PolygonVertex> polygons;        ///< polygons
  std::vector<TextVertex> texts;              ///< text runs
  std::vector<FillQuad> fill_quads;           ///< fill triangles of larger polygons

  /// Empties every array (keeps the allocations).
  void clear();
};

/// How many pixels of a row the rasteriser shades at once. Both widths give the same bytes.
enum class RasterLanes {
  four,   ///< SSE2 (or scalar lanes off x86-64)
  eight,  ///< AVX2, where the CPU has it; else four
};

/// Rasterises a `SoftwareBatch` into a frame in bands of rows on a thread pool. Each pixel
/// is written by one band, in drawing order, so frames do not depend on the thread count.
class SoftwareRaster {
 public:
  /// A pool of `thread_count` threads (the caller included), shading `lanes` pixels at once.
  explicit SoftwareRaster(int thread_count, RasterLanes lanes = RasterLanes::eight);

  /// Whether this CPU runs the eight-lane rasteriser (AVX2, checked at run time).
  static bool eight_lanes_available();
  /// Threads that rasterise (the caller included).
  int thread_count() const { return pool_.thread_count(); }
  /// The pixels of a row shaded at once: `RasterLanes::eight` only where the CPU has AVX2.
  RasterLanes lanes() const { return lanes_; }
  /// Blends every primitive of `batch`, in order, over `frame` (opaque, rows top first, as
  /// read back; a primitive's rows count from the bottom). Primitives must lie inside the
  /// frame. Alpha stays 255.
  void draw(const SoftwareBatch& batch, Frame& frame);

 private:
  ThreadPool pool_;
  RasterLanes lanes_;
  std::vector<std::vector<std::uint32_t>> band_primitives_;  // per band: primitives that touch it
};

}  // namespace impulse2d::render

// libFuzzer target: two shapes (circle, box, oriented box, polygon, capsule, segment, chain
// link, rounded polygon) and two transforms decoded from the bytes go through the collision jump table in
// both orders. Every manifold must have at most 2 points, finite
// depths and points, a unit normal when touching, and swapping the pair must not turn a
// clear contact into none or make the normal point the same way (except when the centres do
// not differ along the normal: then a fixed direction is chosen by design).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>

#include "core/collide.h"
#include "core/error.h"
#include "core/shape.h"

namespace {

using namespace impulse2d;

/// Reads bytes from the fuzzer's input; zeros once it runs out.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint8_t byte() { return at_ < size_ ? data_[at_++] : 0; }
  /// A number in [low, high] from two bytes.
  float in(float low, float high) {
    const float unit = static_cast<float>(byte() | (byte() << 8)) / 65535.0f;
    return low + (high - low) * unit;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t at_ = 0;
};

/// Kinds 0..3 as before the new shapes (so the older seeds decode as they did), then capsule,
/// segment and rounded polygon; a segment whose kind byte is 128 or more is the middle link of
/// a chain through four decoded points (its ghosts the outer two).
std::optional<Shape> read_shape(Bytes& bytes) {
  const std::uint8_t selector = bytes.byte();
  const int kind = selector % 7;
  try {
    switch (kind) {
      case 0:
        return make_circle(bytes.in(0.01f, 5.0f));
      case 1:
        return make_box({bytes.in(0.01f, 5.0f), bytes.in(0.01f, 5.0f)});
      case 2:
        return make_oriented_box({bytes.in(0.01f, 5.0f), bytes.in(0.01f, 5.0f)});
      case 4: {
        const vec2 center1{bytes.in(-3.0f, 3.0f), bytes.in(-3.0f, 3.0f)};
        const vec2 center2{bytes.in(-3.0f, 3.0f), bytes.in(-3.0f, 3.0f)};
        return make_capsule(center1, center2, bytes.in(0.01f, 2.0f));
      }
      case 5: {
        const vec2 point1{bytes.in(-5.0f, 5.0f), bytes.in(-5.0f, 5.0f)};
        const vec2 point2{bytes.in(-5.0f, 5.0f), bytes.in(-5.0f, 5.0f)};
        if (selector < 128) return make_segment(point1, point2);
        const vec2 ghost1{bytes.in(-5.0f, 5.0f), bytes.in(-5.0f, 5.0f)};
        const vec2 ghost2{bytes.in(-5.0f, 5.0f), bytes.in(-5.0f, 5.0f)};
        const vec2 points[4] = {ghost1, point1, point2, ghost2};
        return make_chain(points, 4, false)[1].shape;
      }
      default: {  // 3: a polygon; 6: a rounded one
        const int count = 3 + bytes.byte() % (max_polygon_vertices - 2);
        vec2 vertices[max_polygon_vertices];
        for (int i = 0; i < count; ++i) vertices[i] = {bytes.in(-5.0f, 5.0f), bytes.in(-5.0f, 5.0f)};
        if (kind == 3) return make_polygon(vertices, count);
        return make_rounded_polygon(vertices, count, bytes.in(0.0f, 1.0f));
      }
    }
  } catch (const Error&) {
    return std::nullopt;  // concave, degenerate, equal ends: rejected by design
  }
}

Transform read_transform(Bytes& bytes) {
  return Transform{{bytes.in(-6.0f, 6.0f), bytes.in(-6.0f, 6.0f)},
                   Rotation::from_angle(bytes.in(-7.0f, 7.0f))};
}

void check(const Manifold& manifold) {
  if (manifold.point_count < 0 || manifold.point_count > 2) std::abort();
  if (manifold.point_count == 0) return;
  if (std::fabs(std::sqrt(length_squared(manifold.normal)) - 1.0f) > 1e-3f) std::abort();
  for (int i = 0; i < manifold.point_count; ++i) {
    if (!std::isfinite(manifold.points[i].depth) || !is_finite(manifold.points[i].point)) {
      std::abort();
    }
  }
}

/// Prints what broke (for the crash report), then aborts.
[[noreturn]] void fail(const char* invariant, const Manifold& ab, const Manifold& ba,
                       const Transform& xa, const Transform& xb) {
  std::fprintf(stderr,
               "narrow phase: %s\n A->B normal (%g, %g), %d points; B->A normal (%g, %g), %d "
               "points\n A at (%g, %g), B at (%g, %g)\n",
               invariant, ab.normal.x, ab.normal.y, ab.point_count, ba.normal.x, ba.normal.y,
               ba.point_count, xa.position.x, xa.position.y, xb.position.x, xb.position.y);
  for (int i = 0; i < ab.point_count; ++i) std::fprintf(stderr, " A->B depth %g\n", ab.points[i].depth);
  for (int i = 0; i < ba.point_count; ++i) std::fprintf(stderr, " B->A depth %g\n", ba.points[i].depth);
  std::abort();
}

float deepest(const Manifold& manifold) {
  float depth = 0.0f;
  for (int i = 0; i < manifold.point_count; ++i) depth = std::fmax(depth, manifold.points[i].depth);
  return depth;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes bytes(data, size);
  const std::optional<Shape> a = read_shape(bytes);
  const std::optional<Shape> b = read_shape(bytes);
  if (!a || !b) return 0;
  const Transform xa = read_transform(bytes);
  const Transform xb = read_transform(bytes);
  const Manifold ab = collide(*a, xa, *b, xb);
  const Manifold ba = collide(*b, xb, *a, xa);
  check(ab);
  check(ba);
  // Symmetry, away from grazing contact (where either order may round to "not touching").
  const float clear = 1e-3f;
  if ((deepest(ab) > clear && ba.point_count == 0) || (deepest(ba) > clear && ab.point_count == 0)) {
    fail("contact in one order only", ab, ba, xa, xb);
  }
  // The normal's direction is well defined only for a shallow overlap whose centres differ
  // along it by a tenth of the smaller shape (two thin shapes crossing near their centres
  // have no preferred side): in a deep overlap the separating-axis test may pick another face in the other
  // order (a tie within its tolerance), and with centres level along the normal the collide
  // functions pick a fixed direction (+y for coincident circles) in either order, by design.
  const Aabb box_a = compute_aabb(*a, xa);
  const Aabb box_b = compute_aabb(*b, xb);
  const vec2 size_a = box_a.upper - box_a.lower;
  const vec2 size_b = box_b.upper - box_b.lower;
  const float smallest = std::fmin(std::fmin(size_a.x, size_a.y), std::fmin(size_b.x, size_b.y));
  const float shallow = 0.1f * smallest;
  const float along = glm::dot(xb.position - xa.position, ab.normal);
  // Two polygons can also have two faces whose separations lie within the reference-face
  // tolerance of collide_polygons.cpp (5 % of the depth plus 1 mm); that test favours the
  // first shape, so each order may take the other shape's face, and the normals differ while
  // the depths agree. Only normals that differ with depths outside that tolerance are wrong.
  const float depth_ab = deepest(ab);
  const float depth_ba = deepest(ba);
  const bool depths_disagree =
      std::fabs(depth_ab - depth_ba) > 0.05f * std::fmax(depth_ab, depth_ba) + 0.001f;
  if (std::fabs(along) > 0.1f * smallest && depth_ab > clear && depth_ba > clear &&
      depth_ab < shallow && depth_ba < shallow && glm::dot(ab.normal, ba.normal) > 0.0f &&
      depths_disagree) {
    fail("normals point the same way in both orders", ab, ba, xa, xb);
  }
  return 0;
}

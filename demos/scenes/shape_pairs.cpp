/// @file shape_pairs.cpp
/// The whole collision jump table at work, one cell per pair: in row A, column B a body of
/// kind B falls on a body of kind A. A is created before B, so the pair's first body (the
/// smaller slot) is A and the contact goes through collide[A][B].
///
/// Rows A: circle, box, polygon (the tutorial's 3x3 table, the top left block, as it always
/// was), then rounded polygon and capsule (dynamic, resting on a pad as the first three), then
/// a static two-sided segment and a static chain (one-sided links with ghost vertices, its
/// front facing up, a seam under the falling B). Columns B: the dynamic kinds, circle, box,
/// polygon, rounded polygon, capsule. So every pair of the dynamic kinds meets here in both
/// orders, and each of them on a segment and on a chain (a segment or chain link is always
/// static, so it is always A, and two of them never collide).
#include <array>

#include "core/error.h"
#include "core/world.h"
#include "scene/scene.h"
#include "demos/scene_helpers.h"

namespace impulse2d::demos::scenes {
namespace {

constexpr float cell_size = 4.0f;  // metres

/// What a row or a column holds: the jump table's kinds, a rounded polygon and a chain link
/// told apart from the sharp polygon and the two-sided segment they share a `ShapeType` with.
enum class Kind { Circle, Box, Polygon, RoundedPolygon, Capsule, Segment, Chain };

constexpr Kind row_kinds[] = {Kind::Circle,   Kind::Box,     Kind::Polygon, Kind::RoundedPolygon,
                              Kind::Capsule,  Kind::Segment, Kind::Chain};
constexpr Kind column_kinds[] = {Kind::Circle, Kind::Box, Kind::Polygon, Kind::RoundedPolygon,
                                 Kind::Capsule};
constexpr int row_count = static_cast<int>(sizeof(row_kinds) / sizeof(row_kinds[0]));
constexpr int column_count = static_cast<int>(sizeof(column_kinds) / sizeof(column_kinds[0]));

/// The tutorial's pentagon, scaled by `scale` (1: its size in the 3x3 block).
std::array<vec2, 5> pentagon(float scale) {
  return {scale * vec2{0.6f, -0.45f}, scale * vec2{0.75f, 0.25f}, scale * vec2{0.0f, 0.65f},
          scale * vec2{-0.75f, 0.25f}, scale * vec2{-0.6f, -0.45f}};
}

/// The dynamic body of a kind (all about 1.2-1.6 m across).
Shape shape_of_kind(Kind kind) {
  switch (kind) {
    case Kind::Circle:
      return make_circle(0.6f);
    case Kind::Box:
      return make_box({0.6f, 0.45f});
    case Kind::Polygon: {
      const std::array<vec2, 5> outline = pentagon(1.0f);
      return make_polygon(outline.data(), static_cast<int>(outline.size()));
    }
    case Kind::RoundedPolygon: {
      const std::array<vec2, 5> outline = pentagon(0.9f);
      return make_rounded_polygon(outline.data(), static_cast<int>(outline.size()), 0.1f);
    }
    case Kind::Capsule:
      return make_capsule({-0.45f, 0.0f}, {0.45f, 0.0f}, 0.35f);
    case Kind::Segment:  // static only: `add_surface` builds these
    case Kind::Chain:
      break;
  }
  throw Error("shape_pairs: a segment or a chain is never a dynamic body");
}

/// Row A of a static kind: the surface itself, at the height of a pad's top (0.2 m above
/// `origin`), as wide as a pad. The chain is listed left to right (its front faces up), with
/// raised ends and a seam right under where B lands.
void add_surface(World& world, Kind kind, vec2 origin, const Material& material) {
  if (kind == Kind::Segment) {
    add_body(world, BodyType::Static, make_segment({-1.5f, 0.0f}, {1.5f, 0.0f}),
             origin + vec2{0.0f, 0.2f}, material);
    return;
  }
  BodyDef def;
  def.type = BodyType::Static;
  def.position = origin;
  def.material = material;
  const vec2 points[] = {{-1.5f, 0.5f}, {-0.75f, 0.2f}, {0.25f, 0.2f}, {1.0f, 0.2f}, {1.5f, 0.45f}};
  world.create_chain(def, points, 5, false);
}

void build(World& world, const Params& params) {
  const Material pad = materials::static_ground();
  // `rows` 3 is the tutorial's table alone (3 x 3); more rows bring all 5 columns.
  const int rows = static_cast<int>(params.number("rows"));
  const int columns = rows == 3 ? 3 : column_count;
  for (int row = 0; row < rows; ++row) {
    const Kind a = row_kinds[row];
    const bool static_a = a == Kind::Segment || a == Kind::Chain;
    for (int column = 0; column < columns; ++column) {
      const vec2 origin{cell_size * static_cast<float>(column),
                        -cell_size * static_cast<float>(row)};
      if (static_a) {
        add_surface(world, a, origin, pad);
        // B starts about as far above the surface as above A in the rows above (it lands about
        // as late: the goldens' motion frame, step 30, has every pair in contact).
        add_body(world, BodyType::Dynamic, shape_of_kind(column_kinds[column]),
                 origin + vec2{0.25f, 1.9f}, materials::rock(), 0.4f);
        continue;
      }
      add_static_box(world, origin, {1.5f, 0.2f}, pad);
      add_body(world, BodyType::Dynamic, shape_of_kind(a), origin + vec2{0.0f, 0.9f},
               materials::wood());
      add_body(world, BodyType::Dynamic, shape_of_kind(column_kinds[column]),
               origin + vec2{0.25f, 2.8f}, materials::rock(), 0.4f);
    }
  }
}

}  // namespace

Scene shape_pairs() {
  Scene scene;
  scene.name = "shape_pairs";
  scene.description =
      "the whole collision jump table: in row A (circle, box, polygon: the tutorial's 3x3; then rounded "
      "polygon, capsule, static segment, static chain) a B (circle, box, polygon, rounded polygon, capsule) "
      "falls on an A created first, so the contact goes through collide[A][B]";
  scene.params = {{"rows", "rows A drawn: 3 is the tutorial's 3x3 table alone, 7 the whole jump table",
                   static_cast<double>(row_count), 3, static_cast<double>(row_count), true}};
  scene.model.circles = true;
  scene.model.boxes = true;
  scene.model.polygons = true;
  scene.model.capsules = true;
  scene.model.segments = true;
  // Fitted to the bodies as built (the grid of `rows`), 3.0 m of sky above the top row's B.
  scene.view.camera.mode = CameraSpec::Mode::FitWorld;
  scene.view.steps = 240;
  scene.view.draw.flags = draw_shapes | draw_contact_points | draw_contact_normals;
  scene.view.caption =
      "rows A: circle box polygon rounded capsule segment chain | columns B: circle box polygon rounded capsule";
  scene.build = build;
  return scene;
}

}  // namespace impulse2d::demos::scenes

/// @file test_chains.cpp
/// Chains (one-sided segments with ghost vertices) at the default settings (issue 31): a disc
/// rolling and a box sliding across a flat chain's seams feel one flat surface (tiled boxes in
/// the same test show the bump the chain removes), on an open chain and on a closed loop
/// track; links are one-sided; corners push along their own normals; both orders of every
/// pair give mirrored manifolds; bad chains are refused naming the point.

#include "core/collide.h"
#include "core/error.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace impulse2d {
namespace {

/// Frictionless, inelastic: what a slide across seams needs (no rolling, no bounce).
Material ice() { return Material{"Ice", 1.0f, 0.0f, 0.0f, 0.0f}; }
/// Rough, inelastic: a disc rolls on it without slipping.
Material rubber() { return Material{"Rubber", 1.0f, 0.0f, 0.9f, 0.8f}; }

/// Points of a flat line at y = 0 from x = `start`, `links` links of `length` metres each.
std::vector<vec2> flat_points(float start, int links, float length) {
  std::vector<vec2> points;
  for (int i = 0; i <= links; ++i) points.push_back({start + static_cast<float>(i) * length, 0.0f});
  return points;
}

BodyDef static_def(const Material& material) {
  BodyDef def;
  def.type = BodyType::Static;
  def.material = material;
  def.material.density = 0.0f;
  return def;
}

/// The ground a test slides on: a chain, or static boxes tiled side by side (the seams a
/// chain removes).
enum class Ground { Chain, TiledBoxes };

void add_flat_ground(World& world, Ground ground, const Material& material, float start,
                     int links, float length) {
  if (ground == Ground::Chain) {
    const std::vector<vec2> points = flat_points(start, links, length);
    world.create_chain(static_def(material), points.data(), static_cast<int>(points.size()), false);
    return;
  }
  for (int i = 0; i < links; ++i) {
    BodyDef tile = static_def(material);
    tile.position = {start + (static_cast<float>(i) + 0.5f) * length, -0.25f};
    world.create_body(tile, make_box({0.5f * length, 0.25f}));
  }
}

/// Largest |vertical velocity| (m/s) of `body` over the steps after `settle` seconds until it
/// has moved `distance` metres (or `seconds` pass).
struct Ride {
  float largest_vertical_speed = 0.0f;
  float travelled = 0.0f;  ///< metres along x
  float lowest = 1e9f;     ///< lowest centre height, metres
  float highest = -1e9f;   ///< highest centre height after settling, metres
};

Ride ride(World& world, BodyId body, float settle, float distance, float seconds) {
  Ride result;
  const float start_x = world.body(body).transform.position.x;
  const int steps = static_cast<int>(std::lround(seconds / world.settings().time_step));
  for (int i = 0; i < steps; ++i) {
    world.step();
    const BodyView view = world.body(body);
    if (world.time() < settle) continue;
    result.largest_vertical_speed =
        std::max(result.largest_vertical_speed, std::fabs(view.linear_velocity.y));
    result.lowest = std::min(result.lowest, view.transform.position.y);
    result.highest = std::max(result.highest, view.transform.position.y);
    result.travelled = view.transform.position.x - start_x;
    if (result.travelled >= distance) break;
  }
  return result;
}

// The bound: 1e-4 m/s, the issue's. A disc rolling at 5 m/s on one flat box has no vertical
// velocity beyond the solver's rounding (2.4e-6 m/s measured).
constexpr float seam_bound = 1e-4f;

Ride roll_disc(Ground ground) {
  World world;
  add_flat_ground(world, ground, rubber(), -2.0f, 100, 0.25f);  // 25 m, 99 seams
  BodyDef disc;
  disc.material = rubber();
  disc.position = {0.0f, 0.5f};
  disc.linear_velocity = {5.0f, 0.0f};
  disc.angular_velocity = -10.0f;  // rolling: v / r
  const BodyId id = world.create_body(disc, make_circle(0.5f));
  return ride(world, id, 0.25f, 20.0f, 6.0f);
}

Ride slide_box(Ground ground) {
  World world;
  add_flat_ground(world, ground, ice(), -2.0f, 100, 0.25f);
  BodyDef box;
  box.material = ice();
  box.position = {0.0f, 0.25f};
  box.linear_velocity = {5.0f, 0.0f};
  const BodyId id = world.create_body(box, make_oriented_box({0.25f, 0.25f}));
  return ride(world, id, 0.25f, 20.0f, 6.0f);
}

TEST(ChainSeams, DiscRolls20MetresAcrossAFlatChainOfOneHundredLinksWithoutABump) {
  const Ride chain = roll_disc(Ground::Chain);
  std::printf("[measured] disc on the chain: largest |vy| %g m/s over %g m\n",
              chain.largest_vertical_speed, chain.travelled);
  EXPECT_GE(chain.travelled, 20.0f);
  EXPECT_LT(chain.largest_vertical_speed, seam_bound);
}

TEST(ChainSeams, BoxSlidesAt5MetresPerSecondAcrossAFlatChainWithoutABump) {
  const Ride chain = slide_box(Ground::Chain);
  EXPECT_GE(chain.travelled, 20.0f);
  EXPECT_LT(chain.largest_vertical_speed, seam_bound);
  // The tiled boxes of the same length: the box's corner catches the seams.
  const Ride tiles = slide_box(Ground::TiledBoxes);
  std::printf("[measured] box sliding at 5 m/s: largest |vy| %g m/s on the chain, %g m/s on tiled boxes\n",
              chain.largest_vertical_speed, tiles.largest_vertical_speed);
  EXPECT_GT(tiles.largest_vertical_speed, 10.0f * seam_bound)
      << "tiled ground no longer shows the bump: the comparison proves nothing";
}

/// A closed loop ridden inside (counter-clockwise: the front sides face in): a 20 m x 6 m
/// rectangle of 0.25 m links starting mid-floor, so the loop's closing seam is on the path.
TEST(ChainSeams, DiscAndBoxCrossTheSeamsOfAClosedLoopTrackIncludingItsClosingSeam) {
  std::vector<vec2> points;
  const float step = 0.25f;
  for (float x = 0.0f; x < 10.0f - 1e-3f; x += step) points.push_back({x, 0.0f});
  for (float y = 0.0f; y < 6.0f - 1e-3f; y += step) points.push_back({10.0f, y});
  for (float x = 10.0f; x > -10.0f + 1e-3f; x -= step) points.push_back({x, 6.0f});
  for (float y = 6.0f; y > 1e-3f; y -= step) points.push_back({-10.0f, y});
  for (float x = -10.0f; x < -1e-3f; x += step) points.push_back({x, 0.0f});
  for (const bool box : {false, true}) {
    World world;
    const Material material = box ? ice() : rubber();
    world.create_chain(static_def(material), points.data(), static_cast<int>(points.size()), true);
    BodyDef def;
    def.material = material;
    def.position = {-8.0f, box ? 0.25f : 0.5f};
    def.linear_velocity = {4.0f, 0.0f};
    def.angular_velocity = box ? 0.0f : -8.0f;
    const BodyId id = world.create_body(def, box ? make_oriented_box({0.25f, 0.25f}) : make_circle(0.5f));
    const Ride result = ride(world, id, 0.25f, 15.0f, 5.0f);
    std::printf("[measured] %s on the loop track: largest |vy| %g m/s over %g m\n", box ? "box" : "disc",
                result.largest_vertical_speed, result.travelled);
    EXPECT_GE(result.travelled, 15.0f) << (box ? "box" : "disc");
    EXPECT_LT(result.largest_vertical_speed, seam_bound) << (box ? "box" : "disc");
  }
}

TEST(ChainLinks, CollideFromTheFrontOnly) {
  World world;
  const std::vector<vec2> points = flat_points(-5.0f, 10, 1.0f);
  world.create_chain(static_def(rubber()), points.data(), static_cast<int>(points.size()), false);
  BodyDef from_below;
  from_below.material = rubber();
  from_below.position = {0.0f, -1.0f};
  from_below.linear_velocity = {0.0f, 8.0f};
  from_below.gravity_scale = 0.0f;
  const BodyId rising = world.create_body(from_below, make_circle(0.25f));
  BodyDef from_above = from_below;
  from_above.position = {2.0f, 2.0f};
  from_above.linear_velocity = {0.0f, 0.0f};
  from_above.gravity_scale = 1.0f;
  const BodyId falling = world.create_body(from_above, make_circle(0.25f));
  for (int i = 0; i < 120; ++i) world.step();
  // Rising through the back of the links: never touched (8 m/s for 2 s).
  EXPECT_NEAR(world.body(rising).transform.position.y, -1.0f + 16.0f, 1e-3f);
  // Falling on the front: rests on the chain at its radius (within the soft step's sink).
  EXPECT_NEAR(world.body(falling).transform.position.y, 0.25f, 5e-3f);
  // Rays: from above they hit, from below they pass.
  EXPECT_TRUE(world.raycast_closest({0.5f, 1.0f}, {0.0f, -2.0f}).has_value());
  EXPECT_FALSE(world.raycast_closest({0.5f, -1.0f}, {0.0f, 2.0f}).has_value());
}

/// Continuous collision against a chain: a bullet disc and a bullet box fired at 300 m/s at
/// the front of a chain (a 5 cm disc moves 5 m a step, a hundred times its size) stop on it;
/// fired at its back, they pass (one-sided).
TEST(ChainLinks, BulletsStopOnTheFrontAndPassTheBack) {
  for (const bool box : {false, true}) {
    for (const bool from_front : {true, false}) {
      WorldSettings settings;
      settings.enable_continuous = true;
      settings.gravity = {0.0f, 0.0f};
      World world(settings);
      const std::vector<vec2> points = flat_points(-5.0f, 20, 0.5f);
      world.create_chain(static_def(rubber()), points.data(), static_cast<int>(points.size()), false);
      BodyDef def;
      def.material = rubber();
      def.is_bullet = true;
      def.position = {0.3f, from_front ? 3.0f : -3.0f};
      def.linear_velocity = {0.0f, from_front ? -300.0f : 300.0f};
      const BodyId bullet =
          world.create_body(def, box ? make_oriented_box({0.05f, 0.05f}) : make_circle(0.05f));
      for (int i = 0; i < 4; ++i) world.step();
      const float y = world.body(bullet).transform.position.y;
      if (from_front) {
        EXPECT_GT(y, 0.0f) << (box ? "box" : "disc") << " tunnelled through the chain";
        EXPECT_LT(y, 0.2f) << (box ? "box" : "disc");
      } else {
        EXPECT_GT(y, 10.0f) << (box ? "box" : "disc") << " was stopped by the back of the chain";
      }
    }
  }
}

/// The body order must not matter: a disc created before the chain (so the disc is each
/// contact's body A and its contacts are measured in its turning frame) rolls down a turned
/// 5 degree chain as one created after it does, without sinking or a kick at a seam. Before the
/// recycling test measured in the fixed body's frame, the disc-first run recycled a rolling
/// contact every other step, sank 1.1 mm and took a 9 mm/s kick across the slope.
TEST(ChainSeams, BodyOrderDoesNotMatterForADiscRollingDownATurnedChain) {
  const float slope = 0.0872665f;  // 5 degrees
  const vec2 normal(std::sin(slope), std::cos(slope));
  float largest[2] = {0.0f, 0.0f};
  float deepest[2] = {0.0f, 0.0f};
  for (int disc_first = 0; disc_first < 2; ++disc_first) {
    World world;
    BodyDef ground = static_def(rubber());
    ground.angle = -slope;
    const std::vector<vec2> points = flat_points(-2.0f, 88, 0.25f);
    BodyDef def;
    def.material = rubber();
    def.position = normal * 0.5f;
    def.linear_velocity = vec2(std::cos(slope), -std::sin(slope)) * 2.0f;
    def.angular_velocity = -4.0f;
    BodyId disc;
    if (disc_first) disc = world.create_body(def, make_circle(0.5f));
    world.create_chain(ground, points.data(), static_cast<int>(points.size()), false);
    if (!disc_first) disc = world.create_body(def, make_circle(0.5f));
    for (int i = 0; i < 240; ++i) {
      world.step();
      for (const Contact& contact : world.contacts()) {
        for (int k = 0; k < contact.point_count; ++k) {
          deepest[disc_first] = std::max(deepest[disc_first], contact.points[k].depth);
        }
      }
      if (world.time() < 0.25) continue;
      largest[disc_first] = std::max(largest[disc_first],
                                     std::fabs(glm::dot(world.body(disc).linear_velocity, normal)));
    }
    EXPECT_LT(largest[disc_first], seam_bound) << (disc_first ? "disc first" : "chain first");
  }
  std::printf("[measured] rolling down a turned chain: |v_n| %g (chain first), %g (disc first); "
              "deepest %g, %g m\n", largest[0], largest[1], deepest[0], deepest[1]);
  // The soft contact's resting overlap (0.07 mm), the same in both orders to 1e-6 m.
  EXPECT_NEAR(deepest[1], deepest[0], 1e-6f);
}

/// Two links meeting at a convex corner (a peak): a disc resting on the peak is pushed along
/// the corner's own normal (straight up when the peak is symmetric), reported once, by the link
/// that starts at the corner.
TEST(ChainLinks, ConvexCornerPushesAlongTheCornerNormalOnce) {
  World world;
  const vec2 points[] = {{-4.0f, -1.0f}, {0.0f, 0.0f}, {4.0f, -1.0f}};
  const std::vector<BodyId> links = world.create_chain(static_def(rubber()), points, 3, false);
  ASSERT_EQ(links.size(), 2u);
  BodyDef def;
  def.material = rubber();
  def.position = {0.0f, 0.5f};
  world.create_body(def, make_circle(0.5f));
  world.step();
  int points_at_peak = 0;
  for (const Contact& contact : world.contacts()) {
    for (int i = 0; i < contact.point_count; ++i) {
      ++points_at_peak;
      EXPECT_NEAR(contact.normal.x, 0.0f, 1e-5f);
      EXPECT_NEAR(std::fabs(contact.normal.y), 1.0f, 1e-5f);
      EXPECT_TRUE(contact.body_a == links[1] || contact.body_b == links[1]);
    }
  }
  EXPECT_EQ(points_at_peak, 1);
}

/// At a flat join the shape's own corner would give a sideways normal (the ghost collision):
/// the link rebuilds the manifold along its face normal.
TEST(ChainLinks, FlatJoinGivesTheFaceNormalWhereALoneSegmentGivesTheCornerNormal) {
  const std::vector<ChainLink> chain = [] {
    const std::vector<vec2> points = flat_points(-1.0f, 2, 1.0f);
    return make_chain(points.data(), 3, false);
  }();
  // A box whose lower-left corner sits 1 mm into the second link, just past the join at x = 0.
  const Shape box = make_oriented_box({0.25f, 0.25f});
  const Transform box_at{{0.2505f, 0.249f}, Rotation{}};
  const Transform second{chain[1].position, Rotation{}};
  const Manifold link = collide(chain[1].shape, second, box, box_at, 0.0f);
  ASSERT_GT(link.point_count, 0);
  EXPECT_NEAR(link.normal.x, 0.0f, 1e-6f);
  EXPECT_NEAR(link.normal.y, 1.0f, 1e-6f);
}

TEST(ChainLinks, BothOrdersGiveMirroredManifolds) {
  const vec2 points[] = {{-2.0f, 0.0f}, {-1.0f, 0.0f}, {0.0f, 0.3f}, {1.0f, 0.0f}, {2.0f, 0.2f}};
  const std::vector<ChainLink> chain = make_chain(points, 5, false);
  const vec2 triangle[] = {{-0.3f, -0.2f}, {0.3f, -0.2f}, {0.0f, 0.3f}};
  const Shape others[] = {make_circle(0.3f), make_box({0.3f, 0.2f}), make_polygon(triangle, 3),
                          make_rounded_polygon(triangle, 3, 0.05f),
                          make_capsule({-0.3f, 0.0f}, {0.3f, 0.0f}, 0.15f)};
  int compared = 0;
  for (const ChainLink& link : chain) {
    const Transform at{link.position, Rotation{}};
    for (const Shape& other : others) {
      for (float x = -2.0f; x <= 2.0f; x += 0.1f) {
        for (const float angle : {0.0f, 0.4f, -1.1f}) {
          const Transform place{{x, 0.25f}, Rotation::from_angle(angle)};
          const Manifold ab = collide(link.shape, at, other, place, 0.02f);
          const Manifold ba = collide(other, place, link.shape, at, 0.02f);
          ASSERT_EQ(ab.point_count, ba.point_count);
          if (ab.point_count == 0) continue;
          ++compared;
          EXPECT_EQ(ab.normal, -ba.normal);
          for (int i = 0; i < ab.point_count; ++i) {
            EXPECT_EQ(ab.points[i].point, ba.points[i].point);
            EXPECT_EQ(ab.points[i].depth, ba.points[i].depth);
            EXPECT_TRUE(std::isfinite(ab.points[i].depth));
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 100);
}

TEST(ChainLinks, BadChainsAreRefusedNamingThePoint) {
  World world;
  auto refused = [&](const BodyDef& def, const std::vector<vec2>& points, bool loop,
                     const std::string& expected) {
    try {
      world.create_chain(def, points.data(), static_cast<int>(points.size()), loop);
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
    EXPECT_EQ(world.body_count(), 0);
  };
  const BodyDef ground = static_def(rubber());
  refused(ground, {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 0.0f}}, false, "points[1] and points[2]");
  refused(ground, {{0.0f, 0.0f}, {1.0f, NAN}}, false, "points[1]");
  refused(ground, {{0.0f, 0.0f}}, false, "needs 2..");
  refused(ground, {{0.0f, 0.0f}, {1.0f, 0.0f}}, true, "needs 3..");
  refused(ground, {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 0.0f}}, true,
          "a loop closes itself");
  BodyDef dynamic = ground;
  dynamic.type = BodyType::Dynamic;
  refused(dynamic, {{0.0f, 0.0f}, {1.0f, 0.0f}}, false, "must be static");
  // A link shape on a body that is not static.
  const std::vector<ChainLink> links = make_chain(std::vector<vec2>{{0.0f, 0.0f}, {1.0f, 0.0f}}.data(), 2, false);
  BodyDef kinematic = ground;
  kinematic.type = BodyType::Kinematic;
  EXPECT_THROW(world.create_body(kinematic, links[0].shape), Error);
}

TEST(ChainLinks, SnapshotRestoresChainsBitForBit) {
  World world;
  const vec2 points[] = {{-6.0f, 2.0f}, {-2.0f, 0.0f}, {2.0f, 0.0f}, {6.0f, 2.0f}};
  world.create_chain(static_def(rubber()), points, 4, false);
  BodyDef def;
  def.material = rubber();
  def.position = {-5.0f, 3.0f};
  world.create_body(def, make_circle(0.3f));
  def.position = {4.0f, 3.0f};
  world.create_body(def, make_oriented_box({0.3f, 0.2f}));
  for (int i = 0; i < 30; ++i) world.step();
  World restored;
  restored.restore_snapshot(world.save_snapshot());
  for (int i = 0; i < 90; ++i) {
    world.step();
    restored.step();
  }
  EXPECT_EQ(world.state_hash(), restored.state_hash());
}

}  // namespace
}  // namespace impulse2d

// The dynamic tree and the persistent tree pairs against brute force on random boxes (insert,
// move, remove), and the world's queries and raycasts against a scan of every body.
#include "core/solver/world_state.h"
#include "core/collide/broad_phase.h"
#include "core/collide/dynamic_tree.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace impulse2d;

namespace {

class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}
  float uniform(float low, float high) { return std::uniform_real_distribution<float>(low, high)(engine_); }
  int below(int count) { return std::uniform_int_distribution<int>(0, count - 1)(engine_); }

 private:
  std::mt19937 engine_;
};

Aabb random_box(Random& random, float extent) {
  const vec2 centre{random.uniform(-extent, extent), random.uniform(-extent, extent)};
  const vec2 half{random.uniform(0.05f, 1.5f), random.uniform(0.05f, 1.5f)};
  return Aabb{centre - half, centre + half};
}

std::vector<std::uint32_t> tree_query(const DynamicTree& tree, const Aabb& box) {
  std::vector<std::uint32_t> found;
  tree.query(box, [&found](std::uint32_t slot) {
    found.push_back(slot);
    return true;
  });
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

TEST(DynamicTree, QueriesMatchBruteForceThroughInsertMoveAndRemove) {
  Random random(7);
  DynamicTree tree;
  std::vector<Aabb> boxes;
  std::vector<std::int32_t> proxies;  // per slot; null once removed
  for (std::uint32_t slot = 0; slot < 600; ++slot) {
    boxes.push_back(random_box(random, 40.0f));
    proxies.push_back(tree.create_proxy(boxes.back(), slot));
  }
  ASSERT_TRUE(tree.is_valid());
  for (int round = 0; round < 6; ++round) {
    for (int k = 0; k < 150; ++k) {  // move some
      const auto slot = static_cast<std::size_t>(random.below(static_cast<int>(boxes.size())));
      if (proxies[slot] == DynamicTree::null_node) continue;
      boxes[slot] = random_box(random, 40.0f);
      tree.move_proxy(proxies[slot], boxes[slot]);
    }
    for (int k = 0; k < 40; ++k) {  // remove some, re-add others
      const auto slot = static_cast<std::size_t>(random.below(static_cast<int>(boxes.size())));
      if (proxies[slot] == DynamicTree::null_node) {
        boxes[slot] = random_box(random, 40.0f);
        proxies[slot] = tree.create_proxy(boxes[slot], static_cast<std::uint32_t>(slot));
      } else {
        tree.destroy_proxy(proxies[slot]);
        proxies[slot] = DynamicTree::null_node;
      }
    }
    ASSERT_TRUE(tree.is_valid()) << "round " << round;
    // Height-balanced: within the AVL bound 1.44 log2(n + 2).
    EXPECT_LE(tree.height(), static_cast<int>(1.44 * std::log2(tree.proxy_count() + 2.0)));
    for (int q = 0; q < 100; ++q) {
      const Aabb query = random_box(random, 45.0f);
      std::vector<std::uint32_t> expected;
      for (std::size_t slot = 0; slot < boxes.size(); ++slot) {
        if (proxies[slot] != DynamicTree::null_node && boxes[slot].overlaps(query)) {
          expected.push_back(static_cast<std::uint32_t>(slot));
        }
      }
      ASSERT_EQ(tree_query(tree, query), expected) << "round " << round << ", query " << q;
    }
  }
  for (std::size_t slot = 0; slot < proxies.size(); ++slot) {
    if (proxies[slot] != DynamicTree::null_node) tree.destroy_proxy(proxies[slot]);
  }
  EXPECT_EQ(tree.proxy_count(), 0);
  EXPECT_EQ(tree.height(), -1);
  EXPECT_TRUE(tree.is_valid());
}

TEST(DynamicTree, RaycastFindsEveryBoxTheSegmentMeets) {
  Random random(11);
  DynamicTree tree;
  std::vector<Aabb> boxes;
  for (std::uint32_t slot = 0; slot < 300; ++slot) {
    boxes.push_back(random_box(random, 20.0f));
    tree.create_proxy(boxes.back(), slot);
  }
  for (int r = 0; r < 200; ++r) {
    const vec2 origin{random.uniform(-25.0f, 25.0f), random.uniform(-25.0f, 25.0f)};
    // Every fifth ray is axis-aligned (a zero component takes the slab test's other branch).
    vec2 translation{random.uniform(-30.0f, 30.0f), random.uniform(-30.0f, 30.0f)};
    if (r % 5 == 0) translation[r % 2] = 0.0f;
    std::vector<std::uint32_t> found;
    tree.raycast(origin, translation, [&found](std::uint32_t slot) {
      found.push_back(slot);
      return true;
    });
    // Every box holding a sample point of the segment must be among those found.
    for (int s = 0; s <= 200; ++s) {
      const vec2 point = origin + translation * (static_cast<float>(s) / 200.0f);
      for (std::uint32_t slot = 0; slot < boxes.size(); ++slot) {
        if (boxes[slot].contains(point)) {
          ASSERT_NE(std::find(found.begin(), found.end(), slot), found.end())
              << "ray " << r << " misses box " << slot;
        }
      }
    }
  }
}

namespace {

// Bodies for BroadPhase::find_pairs: types and awake flags as a world would have them.
struct PairScene {
  std::vector<Body> bodies;
  std::vector<std::uint8_t> alive;
  std::vector<Aabb> bounds;
};

Body random_body(Random& random, std::uint32_t slot) {
  Body body;
  body.id = BodyId{slot, 1};
  const int kind = random.below(10);
  body.type = kind == 0 ? BodyType::Static : kind == 1 ? BodyType::Kinematic : BodyType::Dynamic;
  body.awake = random.below(4) != 0;
  body.collision_layers = random.below(8) == 0 ? 2u : 1u;
  return body;
}

}  // namespace

// The tree pairing alone and with its queries shared among four workers (in the smallest parts
// the pool allows) against brute force.
TEST(BroadPhaseTree, PairsMatchBruteForceAsBodiesMoveComeAndGo) {
  Random random(3);
  PairScene scene;
  BroadPhase tree_phase;
  BroadPhase shared_phase;
  BroadPhase brute_phase;
  WorkerPool pool(4);
  pool.set_smallest_chunk(1);
  for (std::uint32_t slot = 0; slot < 400; ++slot) {
    scene.bodies.push_back(random_body(random, slot));
    scene.alive.push_back(1);
    scene.bounds.push_back(random_box(random, 12.0f));
    tree_phase.add_body(slot, scene.bodies[slot].type, scene.bounds[slot]);
    shared_phase.add_body(slot, scene.bodies[slot].type, scene.bounds[slot]);
  }
  std::vector<BodyPair> from_tree;
  std::vector<BodyPair> from_shared;
  std::vector<BodyPair> from_brute;
  for (int step = 0; step < 60; ++step) {
    for (std::uint32_t slot = 0; slot < scene.bodies.size(); ++slot) {
      if (!scene.alive[slot] || scene.bodies[slot].type == BodyType::Static) continue;
      // Small drifts (mostly inside the fat margin) and the odd jump.
      const vec2 shift = random.below(20) == 0
                             ? vec2{random.uniform(-5.0f, 5.0f), random.uniform(-5.0f, 5.0f)}
                             : vec2{random.uniform(-0.04f, 0.04f), random.uniform(-0.04f, 0.04f)};
      scene.bounds[slot].lower += shift;
      scene.bounds[slot].upper += shift;
      if (random.below(30) == 0) scene.bodies[slot].awake = !scene.bodies[slot].awake;
    }
    for (int k = 0; k < 5; ++k) {  // remove a body, or put a new one in a free slot
      const auto slot = static_cast<std::uint32_t>(random.below(static_cast<int>(scene.bodies.size())));
      if (scene.alive[slot]) {
        scene.alive[slot] = 0;
        tree_phase.remove_body(slot);
        shared_phase.remove_body(slot);
      } else {
        scene.bodies[slot] = random_body(random, slot);
        scene.alive[slot] = 1;
        scene.bounds[slot] = random_box(random, 12.0f);
        tree_phase.add_body(slot, scene.bodies[slot].type, scene.bounds[slot]);
        shared_phase.add_body(slot, scene.bodies[slot].type, scene.bounds[slot]);
      }
    }
    if (step == 30) {  // a body whose bounds went non-finite is tested against every body
      scene.bounds[5].lower.x = std::nanf("");
    } else if (step == 33) {
      scene.bounds[5] = random_box(random, 12.0f);
    }
    tree_phase.find_pairs(scene.bodies, scene.alive, scene.bounds, BroadPhaseMethod::DynamicTree,
                          from_tree);
    shared_phase.find_pairs(scene.bodies, scene.alive, scene.bounds,
                            BroadPhaseMethod::DynamicTree, from_shared, &pool);
    brute_phase.find_pairs(scene.bodies, scene.alive, scene.bounds, BroadPhaseMethod::BruteForce,
                           from_brute);
    ASSERT_EQ(from_tree, from_brute) << "step " << step;
    ASSERT_EQ(from_shared, from_brute) << "step " << step;
    for (BodyType type : {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic}) {
      ASSERT_TRUE(tree_phase.tree(type).is_valid()) << "step " << step;
    }
  }
  EXPECT_GT(from_brute.size(), 100u);  // the scene is dense enough to mean something
}

namespace {

// Scattered bodies of every shape, some static, some on a second layer, stepped for a while.
World make_query_world() {
  WorldSettings settings;
  settings.broad_phase = BroadPhaseMethod::SortAndSweep;  // the trees serve queries under any
  World world(settings);
  Random random(5);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.position = {0.0f, -1.0f};
  world.create_body(ground, make_box({30.0f, 1.0f}));
  const vec2 triangle[3] = {{-0.5f, -0.4f}, {0.5f, -0.4f}, {0.0f, 0.6f}};
  for (int i = 0; i < 250; ++i) {
    BodyDef def;
    def.position = {random.uniform(-25.0f, 25.0f), random.uniform(0.5f, 30.0f)};
    def.angle = random.uniform(-3.0f, 3.0f);
    def.linear_velocity = {random.uniform(-5.0f, 5.0f), random.uniform(-5.0f, 5.0f)};
    def.type = i % 17 == 0 ? BodyType::Static : BodyType::Dynamic;
    def.collision_layers = i % 5 == 0 ? 2u : 1u;
    switch (i % 3) {
      case 0: world.create_body(def, make_circle(random.uniform(0.1f, 0.8f))); break;
      case 1: world.create_body(def, make_oriented_box({random.uniform(0.1f, 0.9f), 0.3f})); break;
      default: world.create_body(def, make_polygon(triangle, 3)); break;
    }
  }
  return world;
}

}  // namespace

TEST(TreeQueries, QueriesAndRaycastsMatchAScanOfEveryBody) {
  World world = make_query_world();
  Random random(9);
  for (int round = 0; round < 4; ++round) {
    for (int s = 0; s < 40; ++s) world.step();
    // Teleports and removals between steps must be seen at once.
    const std::vector<BodyId> ids = world.body_ids();
    world.set_transform(ids[10 + round], {random.uniform(-20.0f, 20.0f), 12.0f}, 0.3f);
    world.remove_body(ids[20 + round]);
    const WorldState& state = WorldState::of(world);
    const std::vector<Body>& slots = state.bodies;
    for (int q = 0; q < 60; ++q) {
      const Aabb box = random_box(random, 25.0f);
      std::vector<std::uint32_t> expected;
      std::vector<std::uint32_t> found;
      for (std::uint32_t i = 0; i < slots.size(); ++i) {
        if (state.alive[i] && compute_aabb(slots[i].shape, slots[i].transform).overlaps(box)) {
          expected.push_back(i);
        }
      }
      world.query_aabb(box, [&found](BodyId id) {
        found.push_back(id.index);
        return true;
      });
      ASSERT_EQ(found, expected) << "round " << round << ", box " << q;

      const vec2 point{random.uniform(-25.0f, 25.0f), random.uniform(-1.0f, 30.0f)};
      expected.clear();
      found.clear();
      for (std::uint32_t i = 0; i < slots.size(); ++i) {
        if (state.alive[i] && shape_contains_point(slots[i].shape, slots[i].transform, point)) {
          expected.push_back(i);
        }
      }
      world.query_point(point, [&found](BodyId id) {
        found.push_back(id.index);
        return true;
      });
      ASSERT_EQ(found, expected) << "round " << round << ", point " << q;

      const vec2 origin{random.uniform(-30.0f, 30.0f), random.uniform(-2.0f, 32.0f)};
      const vec2 translation{random.uniform(-40.0f, 40.0f), random.uniform(-40.0f, 40.0f)};
      const std::uint32_t layers = q % 3 == 0 ? 2u : 0xFFFFFFFFu;
      std::vector<RayHit> scanned;
      for (std::uint32_t i = 0; i < slots.size(); ++i) {
        ShapeRayHit hit;
        if (state.alive[i] && (slots[i].collision_layers & layers) != 0 &&
            raycast_shape(slots[i].shape, slots[i].transform, origin, translation, &hit)) {
          scanned.push_back(RayHit{slots[i].id, origin + translation * hit.fraction, hit.normal, hit.fraction});
        }
      }
      std::stable_sort(scanned.begin(), scanned.end(),
                       [](const RayHit& a, const RayHit& b) { return a.fraction < b.fraction; });
      const std::vector<RayHit> all = world.raycast_all(origin, translation, layers);
      ASSERT_EQ(all.size(), scanned.size()) << "round " << round << ", ray " << q;
      for (std::size_t h = 0; h < all.size(); ++h) {
        EXPECT_EQ(all[h].body, scanned[h].body);
        EXPECT_EQ(all[h].fraction, scanned[h].fraction);
      }
      const std::optional<RayHit> closest = world.raycast_closest(origin, translation, layers);
      ASSERT_EQ(closest.has_value(), !scanned.empty());
      if (closest) {
        EXPECT_EQ(closest->body, scanned.front().body);
        EXPECT_EQ(closest->fraction, scanned.front().fraction);
      }
    }
  }
}

// Island batches (core/solver/island_batches.h): the soft step runs all sub-steps of one batch
// of islands before the next. Each island must move exactly as it would alone, bit for bit,
// whatever the worker count.
#include "core/solver/island_batches.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>
#include <vector>

using namespace impulse2d;

namespace {

// Box2D v3's benchmark material: no restitution (so no bounce stage), friction 0.6.
Material crate() { return Material{"Crate", 1.0f, 0.0f, 0.6f, 0.6f}; }

// A wide static ground holding `pyramids` pyramids of `rows` rows of unit boxes, `spacing`
// metres apart (far enough that no two pyramids make contacts); with `only` >= 0 the world
// holds pyramid `only` alone, where it stands among the others.
void build_pyramids(World& world, int pyramids, int rows, float spacing, int only = -1) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = crate();
  ground.position = {0.5f * spacing * static_cast<float>(pyramids), -1.0f};
  world.create_body(ground, make_box({spacing * static_cast<float>(pyramids), 1.0f}));
  for (int p = 0; p < pyramids; ++p) {
    if (only >= 0 && p != only) continue;
    const float centre = spacing * static_cast<float>(p);
    for (int row = 0; row < rows; ++row) {
      for (int i = 0; i < rows - row; ++i) {
        BodyDef box;
        box.material = crate();
        box.position = {centre + static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1),
                        0.5f + static_cast<float>(row)};
        world.create_body(box, make_oriented_box({0.5f, 0.5f}));
      }
    }
  }
}

// The bytes of a body's pose and velocities.
std::vector<unsigned char> motion_bytes(const Body& body) {
  const float values[6] = {body.transform.position.x, body.transform.position.y, body.angle,
                           body.linear_velocity.x,    body.linear_velocity.y,    body.angular_velocity};
  std::vector<unsigned char> bytes(sizeof values);
  std::memcpy(bytes.data(), values, sizeof values);
  return bytes;
}

constexpr int kPyramids = 72;  // ~7200 contacts: four batches
constexpr int kRows = 10;  // 55 boxes, ~100 contacts a pyramid
constexpr float kSpacing = 14.0f;

}  // namespace

TEST(IslandBatches, StaticBodiesJoinNothingAndWholeIslandsShareABatch) {
  IslandBatches islands;
  islands.begin(8);
  // Slot 0 is static. Islands: {1, 2, 3} (two contacts and one on the ground), {4, 5}, {6}
  // on the ground alone; slot 7 moves but touches nothing.
  islands.add_contact(0, false, 1, true);
  islands.add_contact(4, true, 5, true);
  islands.add_contact(1, true, 2, true);
  islands.add_contact(0, false, 6, true);
  islands.add_contact(3, true, 2, true);
  islands.make_batches();
  ASSERT_EQ(islands.batch_count(), 1u);  // 5 contacts: far below a batch's target
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(islands.batch_of_contact(k), 0u) << k;
  islands.gather_bodies([](std::size_t slot) { return slot != 0; });
  ASSERT_EQ(islands.body_count(0), 6u);
  ASSERT_EQ(islands.body_count(1), 1u);  // the rest batch
  EXPECT_EQ(islands.bodies_of(1)[0], 7u);
  const std::set<std::uint32_t> batched(islands.bodies_of(0), islands.bodies_of(0) + 6);
  EXPECT_EQ(batched, (std::set<std::uint32_t>{1, 2, 3, 4, 5, 6}));
}

TEST(IslandBatches, BatchesCloseAtTheirTargetAndNeverSplitAnIsland) {
  // Chains of 300 slots joined by 299 contacts each and one contact to the static slot 0:
  // 300 contacts an island; a batch takes islands until it holds the target or more.
  constexpr std::size_t chain = 300;
  constexpr std::size_t chains = 20;
  IslandBatches islands;
  islands.begin(1 + chain * chains);
  std::vector<std::size_t> island_of_contact;
  // The chains' contacts interleaved, so an island's contacts are not contiguous.
  for (std::size_t link = 0; link < chain; ++link) {
    for (std::size_t c = 0; c < chains; ++c) {
      const std::uint32_t first = static_cast<std::uint32_t>(1 + c * chain);
      if (link == 0) {
        islands.add_contact(0, false, first, true);
      } else {
        islands.add_contact(first + static_cast<std::uint32_t>(link) - 1, true,
                            first + static_cast<std::uint32_t>(link), true);
      }
      island_of_contact.push_back(c);
    }
  }
  islands.make_batches();
  const std::size_t per_batch = (IslandBatches::target_contacts + chain - 1) / chain;  // islands
  EXPECT_EQ(islands.batch_count(), (chains + per_batch - 1) / per_batch);
  std::vector<std::uint32_t> batch_of_island(chains, 0xFFFFFFFFu);
  std::vector<std::size_t> contacts_of_batch(islands.batch_count(), 0);
  for (std::size_t k = 0; k < island_of_contact.size(); ++k) {
    const std::uint32_t batch = islands.batch_of_contact(k);
    ASSERT_LT(batch, islands.batch_count());
    std::uint32_t& island_batch = batch_of_island[island_of_contact[k]];
    if (island_batch == 0xFFFFFFFFu) island_batch = batch;
    EXPECT_EQ(island_batch, batch) << "island " << island_of_contact[k] << " split";
    ++contacts_of_batch[batch];
  }
  for (std::size_t b = 0; b + 1 < contacts_of_batch.size(); ++b) {
    EXPECT_GE(contacts_of_batch[b], IslandBatches::target_contacts) << "batch " << b;
    EXPECT_LT(contacts_of_batch[b], IslandBatches::target_contacts + chain) << "batch " << b;
  }
}

TEST(IslandBatches, EachPyramidOfABatchedWorldMovesBitForBitAsIfAlone) {
  // The default settings (the soft step, one thread), batched from two batches on (by default
  // a world needs 32, some 65,000 contacts).
  World world;
  WorldState::of(world).wide_contacts.set_min_island_batches(2);
  build_pyramids(world, kPyramids, kRows, kSpacing);
  for (int step = 0; step < 90; ++step) world.step();
  // The step really ran batch by batch: contacts for more than three batches, no bounce or
  // joint stage.
  ASSERT_GT(world.contacts().size(), 3 * IslandBatches::target_contacts);
  ASSERT_TRUE(WorldState::of(world).wide_contacts.batched());
  ASSERT_GE(WorldState::of(world).wide_contacts.islands().batch_count(), 4u);
  const std::size_t boxes = static_cast<std::size_t>(kRows * (kRows + 1) / 2);
  for (int only = 0; only < kPyramids; ++only) {
    World alone;  // one island: pass by pass
    build_pyramids(alone, kPyramids, kRows, kSpacing, only);
    for (int step = 0; step < 90; ++step) alone.step();
    EXPECT_FALSE(WorldState::of(alone).wide_contacts.batched());  // one island: pass by pass
    const std::vector<Body>& among = WorldState::of(world).bodies;
    const std::vector<Body>& solo = WorldState::of(alone).bodies;
    ASSERT_EQ(solo.size(), boxes + 1);
    for (std::size_t i = 0; i < boxes; ++i) {
      const Body& box_among = among[1 + static_cast<std::size_t>(only) * boxes + i];
      const Body& box_alone = solo[1 + i];
      ASSERT_EQ(motion_bytes(box_among), motion_bytes(box_alone))
          << "pyramid " << only << ", box " << i << ": x " << box_among.transform.position.x
          << " alone " << box_alone.transform.position.x;
    }
  }
}

TEST(IslandBatches, BatchedStepsAreBitIdenticalToOneThreadPassByPass) {
  // One worker at the default (four batches are too few) solves the world pass by pass; two
  // and four workers, batched from two batches on, solve it batch by batch, the batches
  // shared among them.
  std::vector<std::uint64_t> hashes;
  for (const int workers : {1, 2, 4}) {
    WorldSettings settings;
    settings.worker_count = workers;
    World world(settings);
    if (workers > 1) WorldState::of(world).wide_contacts.set_min_island_batches(2);
    build_pyramids(world, kPyramids, kRows, kSpacing);
    // A box thrown into the first pyramid mid-run joins nothing else, and one falling alone
    // lands in the rest batch until it touches the ground.
    BodyDef thrown;
    thrown.material = crate();
    thrown.position = {-6.0f, 3.0f};
    thrown.linear_velocity = {8.0f, 0.0f};
    world.create_body(thrown, make_oriented_box({0.4f, 0.4f}));
    BodyDef falling;
    falling.material = crate();
    falling.position = {0.5f * kSpacing, 12.0f};
    world.create_body(falling, make_oriented_box({0.4f, 0.4f}));
    // A kinematic paddle turning between two pyramids pushes both: the contacts never move
    // it, but it moves, so it joins them into one island (integrated with that batch).
    BodyDef paddle;
    paddle.type = BodyType::Kinematic;
    paddle.material = crate();
    paddle.position = {3.5f * kSpacing, 0.6f};
    paddle.angular_velocity = 1.5f;
    world.create_body(paddle, make_oriented_box({6.0f, 0.1f}));
    for (int step = 0; step < 120; ++step) world.step();
    EXPECT_EQ(WorldState::of(world).wide_contacts.batched(), workers > 1) << workers << " workers";
    hashes.push_back(world.state_hash());
  }
  EXPECT_EQ(hashes[1], hashes[0]);
  EXPECT_EQ(hashes[2], hashes[0]);
}

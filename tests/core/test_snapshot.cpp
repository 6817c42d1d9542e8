// Snapshots (issue 32): run 2N == run N + save + restore into a fresh World + run N, for a
// pyramid, a jointed chain and a ball pit in every solver; rollback; corrupt buffers refused.
#include "core/error.h"
#include "core/snapshot.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <vector>

using namespace impulse2d;

namespace {

// Writes the FNV-1a hash of a snapshot's payload (from byte 24) into its header (bytes 16-23),
// so that a payload changed by a test still passes the reader's hash check.
void rehash_payload(std::vector<std::uint8_t>& bytes) {
  std::uint64_t hash = 14695981039346656037ull;
  for (std::size_t i = 24; i < bytes.size(); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  for (int i = 0; i < 8; ++i) bytes[16 + i] = static_cast<std::uint8_t>(hash >> (8 * i));
}

void add_ground(World& world) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0.0f, -1.0f};
  world.create_body(ground, make_box({30.0f, 1.0f}));
}

void pyramid(World& world) {
  add_ground(world);
  for (int row = 0; row < 8; ++row) {
    for (int i = 0; i < 8 - row; ++i) {
      BodyDef def;
      def.position = {-4.0f + static_cast<float>(i) + 0.5f * static_cast<float>(row), 0.5f + static_cast<float>(row)};
      world.create_body(def, make_oriented_box({0.45f, 0.45f}));
    }
  }
}

void chain(World& world) {
  add_ground(world);
  BodyDef anchor;
  anchor.type = BodyType::Static;
  anchor.position = {0.0f, 12.0f};
  BodyId previous = world.create_body(anchor, make_box({0.2f, 0.2f}));
  for (int i = 0; i < 10; ++i) {
    BodyDef link;
    link.position = {0.5f + static_cast<float>(i), 12.0f};
    const BodyId next = world.create_body(link, make_oriented_box({0.5f, 0.1f}));
    RevoluteJointDef joint;
    joint.body_a = previous;
    joint.body_b = next;
    joint.local_anchor_a = i == 0 ? vec2(0.0f) : vec2(0.5f, 0.0f);
    joint.local_anchor_b = {-0.5f, 0.0f};
    world.create_joint(joint);
    previous = next;
  }
  BodyDef weight;
  weight.position = {3.0f, 5.0f};
  world.create_body(weight, make_circle(0.6f));
}

void ball_pit(World& world) {
  add_ground(world);
  BodyDef wall;
  wall.type = BodyType::Static;
  wall.position = {-5.0f, 4.0f};
  world.create_body(wall, make_box({0.5f, 5.0f}));
  wall.position = {5.0f, 4.0f};
  world.create_body(wall, make_box({0.5f, 5.0f}));
  const vec2 triangle[3] = {{-0.3f, -0.2f}, {0.3f, -0.2f}, {0.0f, 0.3f}};
  for (int i = 0; i < 80; ++i) {
    BodyDef def;
    def.position = {-4.0f + 0.6f * static_cast<float>(i % 13), 1.0f + 0.7f * static_cast<float>(i / 13)};
    def.material = i % 4 == 0 ? materials::bouncy_ball() : materials::wood();
    def.enable_hit_events = i % 5 == 0;
    if (i % 7 == 3) {
      world.create_body(def, make_polygon(triangle, 3));
    } else {
      world.create_body(def, make_circle(0.25f));
    }
  }
}

using Builder = std::function<void(World&)>;

std::uint64_t events_hash(const World& world, std::uint64_t hash) {
  auto mix = [&hash](std::uint64_t v) { hash = (hash ^ v) * 1099511628211ull; };
  for (const auto& e : world.contact_events().begin) mix(e.body_a.index * 7919ull + e.body_b.index);
  for (const auto& e : world.contact_events().end) mix(e.body_a.index * 104729ull + e.body_b.index);
  for (const auto& e : world.contact_events().hit) mix(e.body_b.index);
  return hash;
}

}  // namespace

TEST(Snapshot, RunTwoNEqualsRunNSaveRestoreRunN) {
  const std::vector<std::pair<const char*, Builder>> worlds = {{"pyramid", pyramid}, {"chain", chain}, {"ball_pit", ball_pit}};
  for (SolverMethod method : solver_methods()) {
    for (bool sleeping : {false, true}) {
      for (const auto& [name, build] : worlds) {
        WorldSettings settings = settings_for(method);
        settings.enable_sleeping = sleeping;
        const int n = 90;
        World straight(settings);
        build(straight);
        std::uint64_t straight_events = 0;
        for (int i = 0; i < n; ++i) straight.step();
        for (int i = 0; i < n; ++i) {
          straight.step();
          straight_events = events_hash(straight, straight_events);
        }

        World first(settings);
        build(first);
        for (int i = 0; i < n; ++i) first.step();
        const std::vector<std::uint8_t> bytes = first.save_snapshot();
        World restored;  // fresh, default settings: the snapshot brings its own
        restored.restore_snapshot(bytes);
        EXPECT_EQ(restored.state_hash(), first.state_hash());
        EXPECT_EQ(restored.save_snapshot(), bytes) << name << ": save of a restore differs";
        std::uint64_t restored_events = 0;
        for (int i = 0; i < n; ++i) {
          restored.step();
          restored_events = events_hash(restored, restored_events);
        }
        EXPECT_EQ(restored.state_hash(), straight.state_hash())
            << name << " " << solver_name(method) << (sleeping ? " sleeping" : "");
        EXPECT_EQ(restored_events, straight_events) << name;
        EXPECT_EQ(restored.step_count(), straight.step_count());
        EXPECT_EQ(restored.joint_count(), straight.joint_count());
      }
    }
  }
}

// Rollback: save, run 10 steps with input A, restore, run with B, restore, run with A again:
// identical to the first A.
TEST(Snapshot, RollbackReplaysTheSameInput) {
  World world;
  ball_pit(world);
  for (int i = 0; i < 30; ++i) world.step();
  const std::vector<BodyId> ids = world.body_ids();
  const BodyId pushed = ids[10];
  auto run = [&](vec2 push) {
    for (int i = 0; i < 10; ++i) {
      world.apply_force_to_center(pushed, push);
      world.step();
    }
    return world.state_hash();
  };
  const std::vector<std::uint8_t> saved = world.save_snapshot();
  const std::uint64_t first_a = run({40.0f, 0.0f});
  world.restore_snapshot(saved);
  const std::uint64_t b = run({-40.0f, 30.0f});
  EXPECT_NE(b, first_a);
  world.restore_snapshot(saved);
  EXPECT_EQ(run({40.0f, 0.0f}), first_a);
}

// Truncated, wrong version, flipped bytes: an Error saying so, never a crash; the world keeps
// its state.
TEST(Snapshot, CorruptBuffersAreErrors) {
  World source;
  chain(source);
  for (int i = 0; i < 20; ++i) source.step();
  const std::vector<std::uint8_t> bytes = source.save_snapshot();
  World target;
  pyramid(target);
  const std::uint64_t before = target.state_hash();
  auto refused = [&](const std::vector<std::uint8_t>& buffer, const char* expected) {
    try {
      target.restore_snapshot(buffer);
      ADD_FAILURE() << "accepted a corrupt buffer (" << expected << ")";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(expected), std::string::npos) << error.what();
    }
    EXPECT_EQ(target.state_hash(), before);
  };
  for (std::size_t length : {std::size_t{0}, std::size_t{3}, std::size_t{23}, std::size_t{24}, bytes.size() / 2, bytes.size() - 1}) {
    refused(std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(length)), "truncated");
  }
  std::vector<std::uint8_t> version = bytes;
  version[4] = 5;
  refused(version, "version 5");
  // Versions 1 (before capsules, segments and rounded polygons), 2 (before chain links) and 3
  // (before compound bodies) are refused cleanly too.
  for (std::uint8_t old : {1, 2, 3}) {
    std::vector<std::uint8_t> old_version = bytes;
    old_version[4] = old;
    refused(old_version, ("snapshot version " + std::to_string(old) + ", this build reads version 4").c_str());
  }
  std::vector<std::uint8_t> magic = bytes;
  magic[0] ^= 0xFF;
  refused(magic, "magic");
  for (std::size_t at = 24; at < bytes.size(); at += 37) {
    std::vector<std::uint8_t> flipped = bytes;
    flipped[at] ^= 0x10;
    refused(flipped, "corrupt");
  }
  // A payload changed with its hash recomputed still meets the reader's checks.
  int rejected = 0, accepted = 0;
  for (std::size_t at = 24; at < bytes.size(); at += 11) {
    std::vector<std::uint8_t> flipped = bytes;
    flipped[at] ^= 0xFF;
    rehash_payload(flipped);
    World scratch;
    try {
      scratch.restore_snapshot(flipped);
      ++accepted;  // a changed float: a different but well-formed world
    } catch (const Error&) {
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 0);
  EXPECT_GT(accepted, 0);
  target.restore_snapshot(bytes);
  EXPECT_EQ(target.state_hash(), source.state_hash());
}

// A contact saved with no points (the narrow phase keeps none such) is refused by name, with
// its payload hash right: the solvers read a kept contact's first point unasked.
TEST(Snapshot, AContactWithoutPointsIsRefused) {
  World source;
  add_ground(source);
  BodyDef box;
  box.type = BodyType::Dynamic;
  box.position = {0.0f, 0.5f};  // resting on the ground
  source.create_body(box, make_box({0.5f, 0.5f}));
  for (int i = 0; i < 5; ++i) source.step();
  ASSERT_EQ(source.contacts().size(), 1u);
  const Contact& contact = source.contacts()[0];
  std::vector<std::uint8_t> bytes = source.save_snapshot();
  // The contact's normal and point count, as the snapshot writes them (little-endian).
  std::uint8_t pattern[12];
  std::memcpy(pattern, &contact.normal.x, 4);
  std::memcpy(pattern + 4, &contact.normal.y, 4);
  const std::int32_t count = contact.point_count;
  std::memcpy(pattern + 8, &count, 4);
  const auto at = std::search(bytes.begin(), bytes.end(), std::begin(pattern), std::end(pattern));
  ASSERT_NE(at, bytes.end());
  std::fill(at + 8, at + 12, std::uint8_t{0});
  rehash_payload(bytes);
  World target;
  try {
    target.restore_snapshot(bytes);
    ADD_FAILURE() << "accepted a contact without points";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("corrupt contact point count 0"), std::string::npos)
        << error.what();
  }
}

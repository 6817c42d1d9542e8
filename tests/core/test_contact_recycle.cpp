// Contact recycling (core/contact_recycle.h): a kept manifold tracks separation exactly like a
// fresh one for small motions, is recomputed once the relative pose moves past the recycle
// distance or a body turns past 11.5 degrees, and never for bullets.
#include "core/solver/contact_recycle.h"
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace impulse2d;

namespace {

// Two rotating unit boxes, B resting on A with `depth` of overlap, after one step has made
// their contact (gravity off, so nothing moves by itself).
struct Pair {
  World world;
  BodyId a, b;
  explicit Pair(float depth) : world(no_gravity()) {
    BodyDef def;
    def.material = Material{"Box", 1.0f, 0.0f, 0.5f, 0.5f};
    a = world.create_body(def, make_oriented_box({0.5f, 0.5f}));
    def.position = {0.0f, 1.0f - depth};
    b = world.create_body(def, make_oriented_box({0.5f, 0.5f}));
  }
  static WorldSettings no_gravity() {
    WorldSettings settings;
    settings.gravity = {0.0f, 0.0f};
    return settings;
  }
  const Contact& contact() const { return world.contacts().at(0); }
  const Body& body(BodyId id) const { return WorldState::of(world).bodies[id.index]; }
};

TEST(ContactRecycle, AFreshManifoldIsRecordedAndAStillPairIsKept) {
  Pair pair(0.01f);
  pair.world.step();
  ASSERT_EQ(pair.world.contacts().size(), 1u);
  const Contact& contact = pair.contact();
  EXPECT_FALSE(contact.recycled);
  EXPECT_TRUE(may_recycle(pair.body(pair.a), pair.body(pair.b), contact, 0.05f, 0.02f));
  EXPECT_FALSE(may_recycle(pair.body(pair.a), pair.body(pair.b), contact, 0.0f, 0.02f));
}

// Kept separation = fresh separation to first order: moving B straight up by d changes the
// kept depth by exactly d (the normal is vertical, the anchors move with the centres).
TEST(ContactRecycle, KeptDepthFollowsAStraightMoveExactly) {
  Pair pair(0.01f);
  pair.world.step();
  Contact kept = pair.contact();
  // The depth at the bodies' current poses (the step moved them since its narrow phase).
  recycle_manifold(pair.body(pair.a), pair.body(pair.b), kept);
  const float before = kept.points[0].depth;
  Body moved = pair.body(pair.b);
  moved.transform.position.y += 0.004f;
  recycle_manifold(pair.body(pair.a), moved, kept);
  EXPECT_NEAR(kept.points[0].depth, before - 0.004f, 1e-6f);
  EXPECT_NEAR(kept.points[1].depth, before - 0.004f, 1e-6f);
}

// Past the distance (a 6 cm slide against 5 cm), or a turn past 11.5 degrees, the manifold
// is computed afresh; a bullet never keeps one.
TEST(ContactRecycle, LargeMotionTurnsAndBulletsCollideAfresh) {
  Pair pair(0.01f);
  pair.world.step();
  const Contact& contact = pair.contact();
  Body slid = pair.body(pair.b);
  slid.transform.position.x += 0.06f;
  EXPECT_FALSE(may_recycle(pair.body(pair.a), slid, contact, 0.05f, 0.02f));
  Body turned = pair.body(pair.b);
  turned.transform.rotation = Rotation::from_angle(0.21f);  // 12 degrees, both bodies' frames
  Body turned_a = pair.body(pair.a);
  turned_a.transform.rotation = Rotation::from_angle(0.21f);
  EXPECT_FALSE(may_recycle(turned_a, turned, contact, 1.0f, 1.0f));
  Body bullet = pair.body(pair.b);
  bullet.is_bullet = true;
  EXPECT_FALSE(may_recycle(pair.body(pair.a), bullet, contact, 0.05f, 0.02f));
}

// In a world step: a resting pair keeps its manifold from the second step on; with the
// distance 0 it never does.
TEST(ContactRecycle, WorldKeepsARestingPairsManifold) {
  Pair kept(0.0f);
  kept.world.step();
  kept.world.step();
  EXPECT_TRUE(kept.contact().recycled);
  WorldSettings settings = Pair::no_gravity();
  settings.contact_recycle_distance = 0.0f;
  Pair fresh(0.0f);
  fresh.world.set_settings(settings);
  fresh.world.step();
  fresh.world.step();
  EXPECT_FALSE(fresh.contact().recycled);
}

}  // namespace

// A kept manifold keeps the offsets and effective masses prepare found for it
// (Contact::kept_masses) instead of computing them again each step. A world restored from a
// snapshot keeps none, so it computes them afresh: the two must go on bit for bit alike, also
// across a change of a body's mass while its contacts are kept (which must drop what was kept).
TEST(ContactRecycle, KeptEffectiveMassesGoOnLikeFreshOnesAcrossAMassChange) {
  WorldSettings settings;
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.position = {0.0f, -0.5f};
  world.create_body(ground, make_oriented_box({5.0f, 0.5f}));
  BodyDef box;
  box.material = Material{"Box", 1.0f, 0.0f, 0.6f, 0.5f};
  BodyId top;
  for (int i = 0; i < 3; ++i) {
    box.position = {0.1f * static_cast<float>(i), 0.5f + static_cast<float>(i)};
    top = world.create_body(box, make_oriented_box({0.5f, 0.5f}));
  }
  for (int step = 0; step < 90; ++step) world.step();
  int kept = 0;
  for (const Contact& contact : world.contacts()) kept += contact.recycled && contact.kept_masses ? 1 : 0;
  ASSERT_GT(kept, 0) << "the resting stack's contacts keep their manifolds and masses";

  World restored(settings);
  restored.restore_snapshot(world.save_snapshot());
  for (const Contact& contact : restored.contacts()) EXPECT_FALSE(contact.kept_masses);
  for (World* each : {&world, &restored}) each->set_material(top, Material{"Heavy", 4.0f, 0.0f, 0.6f, 0.5f});
  for (int step = 0; step < 60; ++step) {
    world.step();
    restored.step();
    ASSERT_EQ(world.state_hash(), restored.state_hash()) << "step " << step;
  }
}

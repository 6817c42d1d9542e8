// Contacts of pairs whose bodies all sleep are set aside (World::sleeping_contacts) rather than
// dropped, counted in the step stats, go back to the narrow phase with their impulses when a
// body of the pair wakes, and are dropped when one is teleported or removed.
#include "core/world.h"

#include <gtest/gtest.h>

#include <vector>

using namespace impulse2d;

namespace {

struct Stack {
  BodyId ground;
  std::vector<BodyId> boxes;  // bottom to top
};

Stack build_stack(World& world, int count) {
  Stack stack;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0.0f, -1.0f};
  stack.ground = world.create_body(ground, make_box({5.0f, 1.0f}));
  for (int i = 0; i < count; ++i) {
    BodyDef def;
    def.position = {0.0f, 0.5f + 1.0f * static_cast<float>(i)};
    stack.boxes.push_back(world.create_body(def, make_box({0.5f, 0.5f})));
  }
  return stack;
}

bool has_pair(const std::vector<Contact>& contacts, BodyId a, BodyId b) {
  for (const Contact& contact : contacts) {
    if (contact.body_a == a && contact.body_b == b) return true;
  }
  return false;
}

// Steps until every body sleeps, then once more so the step begins with them asleep.
void step_until_asleep(World& world) {
  for (int i = 0; i < 1200; ++i) {
    world.step();
    if (world.stats().awake_body_count == 0) break;
  }
  ASSERT_EQ(world.stats().awake_body_count, 0);
  world.step();
}

}  // namespace

TEST(SleepingContacts, AreKeptWithTheirImpulsesWhileTheStackSleeps) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  const Stack stack = build_stack(world, 3);
  step_until_asleep(world);

  EXPECT_TRUE(world.contacts().empty());
  const std::vector<Contact>& sleeping = world.sleeping_contacts();
  ASSERT_EQ(sleeping.size(), 3u);
  EXPECT_EQ(world.stats().sleeping_contact_count, 3);
  EXPECT_EQ(world.stats().contact_count, 0);
  EXPECT_TRUE(has_pair(sleeping, stack.ground, stack.boxes[0]));
  EXPECT_TRUE(has_pair(sleeping, stack.boxes[0], stack.boxes[1]));
  EXPECT_TRUE(has_pair(sleeping, stack.boxes[1], stack.boxes[2]));
  for (std::size_t i = 1; i < sleeping.size(); ++i) {  // sorted by pair
    EXPECT_TRUE(sleeping[i - 1].body_a.index < sleeping[i].body_a.index ||
                (sleeping[i - 1].body_a.index == sleeping[i].body_a.index &&
                 sleeping[i - 1].body_b.index < sleeping[i].body_b.index));
  }
  for (const Contact& contact : sleeping) {
    float load = 0.0f;
    for (int p = 0; p < contact.point_count; ++p) load += contact.points[p].normal_impulse;
    EXPECT_GT(load, 0.0f) << "pair " << contact.body_a.index << "-" << contact.body_b.index;
  }

  // More steps asleep change nothing.
  for (int i = 0; i < 30; ++i) world.step();
  EXPECT_EQ(world.sleeping_contacts().size(), 3u);
  EXPECT_TRUE(world.contacts().empty());
}

TEST(SleepingContacts, LeaveTheListWhenABodyWakesMovesOrIsRemoved) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  const Stack stack = build_stack(world, 3);
  step_until_asleep(world);
  ASSERT_EQ(world.sleeping_contacts().size(), 3u);

  // Waking the top box brings its contact back to the narrow phase, which keeps it (the pose
  // did not change, so the manifold is recycled) with its impulses for warm starting.
  world.set_awake(stack.boxes[2], true);
  world.step();
  ASSERT_TRUE(has_pair(world.contacts(), stack.boxes[1], stack.boxes[2]));
  for (const Contact& contact : world.contacts()) {
    if (contact.body_a == stack.boxes[1] && contact.body_b == stack.boxes[2]) {
      EXPECT_TRUE(contact.recycled);
    }
  }
  EXPECT_FALSE(has_pair(world.sleeping_contacts(), stack.boxes[1], stack.boxes[2]));
  EXPECT_EQ(world.stats().contact_count + world.stats().sleeping_contact_count, 3);

  // A teleported body's set-aside contacts go at once; a removed body's too.
  step_until_asleep(world);
  ASSERT_EQ(world.sleeping_contacts().size(), 3u);
  world.set_transform(stack.boxes[2], {3.0f, 4.0f}, 0.0f);
  EXPECT_EQ(world.sleeping_contacts().size(), 2u);
  world.remove_body(stack.boxes[0]);
  EXPECT_TRUE(world.sleeping_contacts().empty());
}

// The narrow phase's contact list (narrow_phase.h): this step's list is written over last
// step's, and old contacts that new ones displace before they are read wait in a small ring.
// New pairs that begin ahead of every old one must leave a list sorted by pair, with one
// contact per touching pair, each kept contact carrying what it held, and a ring no larger
// than the new contacts ahead of the old (not a second copy of the list).
#include "core/solver/world_state.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <set>
#include <utility>

using namespace impulse2d;

namespace {

constexpr int pair_count = 24;  // pairs of circles; the first `new_pairs` meet only in step 2
constexpr int new_pairs = 10;

// Circle pairs (2k, 2k + 1), 10 m apart from each other pair; a pair overlaps by 0.1 m when
// `together`, else it is 3 m apart.
void place_pair(World& world, const std::vector<BodyId>& bodies, int k, bool together) {
  const float x = 10.0f * static_cast<float>(k);
  world.set_transform(bodies[static_cast<std::size_t>(2 * k)], {x, 0.0f}, 0.0f);
  world.set_transform(bodies[static_cast<std::size_t>(2 * k + 1)], {x + (together ? 0.9f : 3.0f), 0.0f}, 0.0f);
}

void check_list(int workers) {
  WorldSettings settings;
  settings.gravity = {0.0f, 0.0f};
  settings.worker_count = workers;
  World world(settings);
  std::vector<BodyId> bodies;
  for (int i = 0; i < 2 * pair_count; ++i) bodies.push_back(world.create_body(BodyDef{}, make_circle(0.5f)));
  for (int k = 0; k < pair_count; ++k) place_pair(world, bodies, k, k >= new_pairs);
  world.step();
  ASSERT_EQ(world.contacts().size(), static_cast<std::size_t>(pair_count - new_pairs));
  // Markers on old contacts at the start, middle and end of the old list: a turned-off pair
  // stays off while its shapes overlap, so the mark must travel with the contact.
  const std::set<int> marked{new_pairs, new_pairs + 7, pair_count - 1};
  for (const int k : marked) {
    ASSERT_TRUE(world.set_contact_enabled(bodies[static_cast<std::size_t>(2 * k)],
                                          bodies[static_cast<std::size_t>(2 * k + 1)], false));
  }
  // Every new pair begins ahead of every old one.
  for (int k = 0; k < new_pairs; ++k) place_pair(world, bodies, k, true);
  world.step();
  const std::vector<Contact>& contacts = world.contacts();
  ASSERT_EQ(contacts.size(), static_cast<std::size_t>(pair_count)) << workers << " workers";
  for (int k = 0; k < pair_count; ++k) {
    const Contact& contact = contacts[static_cast<std::size_t>(k)];
    EXPECT_EQ(contact.body_a, bodies[static_cast<std::size_t>(2 * k)]) << "contact " << k;
    EXPECT_EQ(contact.body_b, bodies[static_cast<std::size_t>(2 * k + 1)]) << "contact " << k;
    EXPECT_EQ(contact.enabled, marked.count(k) == 0) << "contact " << k << ", " << workers << " workers";
  }
  // The ring held at most the new contacts ahead of the old, never the whole old list.
  EXPECT_LE(WorldState::of(world).spilled_contacts.size(), static_cast<std::size_t>(new_pairs));
  // Pairs that part drop out; those that stay keep their marks.
  for (int k = 0; k < pair_count; k += 2) place_pair(world, bodies, k, false);
  world.step();
  ASSERT_EQ(world.contacts().size(), static_cast<std::size_t>(pair_count / 2));
  for (const Contact& contact : world.contacts()) {
    const int k = static_cast<int>(contact.body_a.index / 2);
    EXPECT_EQ(k % 2, 1);
    EXPECT_EQ(contact.enabled, marked.count(k) == 0) << "contact of pair " << k;
  }
}

}  // namespace

TEST(ContactList, NewPairsAheadOfEveryOldOneKeepTheListSortedAndTheirMarks) { check_list(1); }

TEST(ContactList, TheSameOnTwoWorkers) { check_list(2); }

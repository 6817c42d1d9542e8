// The soft step's wide contact solver: graph colouring (no two contacts of one colour move the
// same body), and results that do not depend on the lane count (4 or 8 contacts per vector).
#include "core/solver/world_state.h"
#include "core/solver/contact_colouring.h"
#include "core/error.h"
#include "core/solver/wide_contact_solver.h"
#include "core/world.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

WorldSettings soft_settings(int lanes) {
  WorldSettings settings;
  settings.solver = SolverMethod::SoftStep;
  settings.substeps = 4;
  settings.velocity_iterations = 1;
  settings.solver_lanes = lanes;
  return settings;
}

// A pyramid on a static ground, a sliding crate, bouncing balls and a kinematic paddle: every
// branch of the kernels (soft push-out, speculative gap, bounce, waiting points, sticking and
// sliding friction, bodies contacts never move) is taken within a few seconds.
void build_mixed_scene(World& world, int rows) {
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0, -0.5f};
  world.create_body(ground, make_box({rows + 20.0f, 0.5f}));
  for (int row = 0; row < rows; ++row) {
    for (int i = 0; i < rows - row; ++i) {
      BodyDef box;
      box.position = {static_cast<float>(i) - 0.5f * static_cast<float>(rows - row - 1),
                      0.5f + static_cast<float>(row)};
      world.create_body(box, make_oriented_box({0.5f, 0.5f}));
    }
  }
  BodyDef crate;
  crate.position = {-rows - 5.0f, 0.5f};
  crate.linear_velocity = {6.0f, 0.0f};
  world.create_body(crate, make_oriented_box({0.5f, 0.5f}));
  for (int i = 0; i < 6; ++i) {
    BodyDef ball;
    ball.material = materials::bouncy_ball();
    ball.position = {rows + 3.0f + 0.9f * static_cast<float>(i), 2.0f + static_cast<float>(i)};
    world.create_body(ball, make_circle(0.4f));
  }
  BodyDef paddle;
  paddle.type = BodyType::Kinematic;
  paddle.position = {rows + 10.0f, 0.6f};
  paddle.angular_velocity = 2.0f;
  world.create_body(paddle, make_oriented_box({2.0f, 0.1f}));
}

}  // namespace

TEST(ContactColouring, NoColourMovesABodyTwiceAndEveryContactIsColouredOnce) {
  World world(soft_settings(0));
  build_mixed_scene(world, 12);
  for (int i = 0; i < 30; ++i) world.step();
  const std::vector<Contact>& contacts = world.contacts();
  ASSERT_GT(contacts.size(), 150u);
  ContactColouring colouring;
  colouring.begin(WorldState::of(world).bodies.size());
  for (const Contact& contact : contacts) colouring.add(contact);
  ASSERT_GT(colouring.colour_count(), 1);
  bool static_body_shared = false;
  std::size_t coloured = 0;
  for (int colour = 0; colour < colouring.colour_count(); ++colour) {
    std::set<std::uint32_t> moved, fixed;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      if (colouring.colour_of(i) != colour) continue;
      ++coloured;
      const Contact& contact = contacts[i];
      const bool moves_a = contact.mass.inverse_mass_a > 0.0f || contact.mass.inverse_inertia_a > 0.0f;
      const bool moves_b = contact.mass.inverse_mass_b > 0.0f || contact.mass.inverse_inertia_b > 0.0f;
      for (auto [moves, slot] : {std::pair{moves_a, contact.body_a.index},
                                 std::pair{moves_b, contact.body_b.index}}) {
        if (moves) {
          EXPECT_TRUE(moved.insert(slot).second) << "colour " << colour << " moves body " << slot << " twice";
        } else if (!fixed.insert(slot).second) {
          static_body_shared = true;
        }
      }
    }
    EXPECT_EQ(colouring.count(colour), coloured) << "colour " << colour;
    coloured = 0;
  }
  EXPECT_TRUE(static_body_shared) << "the ground never shared a colour: bodies contacts never "
                                     "move should not use up colours";
  // Every solvable contact has one colour (a colour or the overflow), the others none.
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const bool solvable = contacts[i].enabled && (contacts[i].mass.inverse_mass_a > 0.0f ||
                                                  contacts[i].mass.inverse_mass_b > 0.0f);
    const int colour = colouring.colour_of(i);
    EXPECT_EQ(colour >= 0, solvable) << "contact " << i;
    EXPECT_TRUE(colour < colouring.colour_count() || colour == ContactColouring::max_colours)
        << "contact " << i << " has colour " << colour;
  }
}

TEST(WideContactSolver, FourAndEightLanesGiveBitIdenticalStates) {
  if (WideContactSolver::widest_lanes() != 8) {
    GTEST_SKIP() << "this CPU has no AVX2: only the 4-lane kernels run here";
  }
  World four(soft_settings(4));
  World eight(soft_settings(8));
  build_mixed_scene(four, 15);
  build_mixed_scene(eight, 15);
  for (int i = 0; i < 240; ++i) {
    four.step();
    eight.step();
    ASSERT_EQ(four.state_hash(), eight.state_hash()) << "diverged at step " << i + 1;
  }
  // The scene did what it is meant to exercise: things bounced, slid and came to rest.
  EXPECT_GT(four.contacts().size(), 100u);
}

TEST(WideContactSolver, AutoPicksTheWidestLanesAndMatchesThem) {
  World automatic(soft_settings(0));
  World widest(soft_settings(WideContactSolver::widest_lanes()));
  build_mixed_scene(automatic, 8);
  build_mixed_scene(widest, 8);
  for (int i = 0; i < 60; ++i) {
    automatic.step();
    widest.step();
  }
  EXPECT_EQ(automatic.state_hash(), widest.state_hash());
}

TEST(WideContactSolver, LaneCountOutsideFourOrEightIsRefusedByName) {
  WorldSettings settings = soft_settings(3);
  try {
    World world(settings);
    world.step();
    FAIL() << "solver_lanes = 3 was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("solver_lanes"), std::string::npos) << error.what();
  }
}

TEST(WideContactSolver, LongRunEndsInThePinnedStateWithEveryCompiler) {
  // Pinned from a GCC 12 build; the Clang (sanitizer) build of scripts/test.sh runs this test
  // too, so both compilers' vector code must give these bits (no FMA, lane-wise IEEE).
  World world(soft_settings(0));
  build_mixed_scene(world, 15);
  for (int i = 0; i < 600; ++i) world.step();
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(world.state_hash()));
  EXPECT_STREQ(hash, "c07d7ae14b8dc239");
}

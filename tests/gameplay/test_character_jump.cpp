// The character's jumps against exact answers: apex heights under the variable-height gravity
// schedule, the coyote and buffer windows to the step, extra jumps, wall slide and wall jump,
// the ceiling.
//
// Apex. The controller sets the take-off speed v0 = sqrt(2 g h) before the step; each step
// uses gravity scale s_k (0.5 while the button is held and the body rises, else 1), so with
// semi-implicit Euler v_k = v_{k-1} - s_k g dt and y_k = y_{k-1} + v_k dt. Holding for H steps
// and then releasing gives y_H = H v0 dt - (g/2) dt^2 H (H+1) / 2, v_H = v0 - H (g/2) dt, then
// a rise of n v_H dt - g dt^2 n (n+1) / 2 with n = floor(v_H / (g dt)) (`discrete_rise`).
// Against the continuous schedule (apex Y): the right-endpoint sum of a velocity that is linear
// on each step gives y_n = y(n dt) - (v0 - v_n) dt / 2 exactly, and near the apex
// y(t) = Y - a (t - t*)^2 / 2 with a the gravity there, so the discrete apex lies in
// [Y - v0 dt/2, Y - v0 dt/2 + a dt^2 / 8]: one step's error, derived, not guessed.
#include "test_character_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::character_test;

namespace {

// Float rounding of the positions summed over `steps` steps of values up to `scale` metres.
double rounding_bound(int steps, double scale) { return steps * scale * std::ldexp(1.0, -23); }

constexpr int settle_steps = 20;  // idle steps on the floor before anything happens

struct JumpRun {
  double rise = 0.0;     // highest centre above the centre before the jump, metres
  double v0 = 0.0;       // take-off speed the controller used, m/s
  int steps = 0;         // steps simulated after the press
};

// Character resting on a floor at y = 0; jump pressed at `settle_steps`, held `hold_steps`
// updates (the press included), then released; runs until it is falling again.
JumpRun jump_and_measure(float dt, int hold_steps, const CharacterSettings& tuning = {}) {
  World world(settings_at(dt));
  add_floor(world, -20.0f, 20.0f, 0.0f);
  CharacterDef def;
  def.position = {0.0f, 0.5f};
  def.settings = tuning;
  Character character(world, def);
  InputScript script;
  script.set(settle_steps, CharacterInput{0.0f, true, false});
  script.set(settle_steps + hold_steps, CharacterInput{});
  run(world, character, script, settle_steps, nullptr);
  EXPECT_TRUE(character.grounded());
  const double start = world.body(character.body()).transform.position.y;
  JumpRun result;
  result.v0 = character.jump_speed(world);
  double highest = start;
  const int flight_steps = static_cast<int>(3.0 / dt);
  run(world, character, script, flight_steps, [&](std::int64_t) {
    highest = std::max(highest, static_cast<double>(world.body(character.body()).transform.position.y));
  });
  result.rise = highest - start;
  result.steps = flight_steps;
  return result;
}

}  // namespace

class ApexHeight : public ::testing::TestWithParam<float> {};

TEST_P(ApexHeight, JumpWithoutVariableHeightPeaksWithinOneStepOfH) {
  const double dt = GetParam();
  CharacterSettings tuning;
  tuning.held_gravity_scale = 1.0f;  // constant gravity: the seed's plain jump
  const JumpRun jump = jump_and_measure(GetParam(), 1, tuning);
  const double h = tuning.jump_height;
  EXPECT_NEAR(jump.v0, std::sqrt(2.0 * g * h), 1e-5);
  EXPECT_NEAR(jump.rise, discrete_rise(jump.v0, g, dt), rounding_bound(jump.steps, 3.0));
  EXPECT_GE(jump.rise, h - jump.v0 * dt / 2 - 1e-5);
  EXPECT_LE(jump.rise, h - jump.v0 * dt / 2 + g * dt * dt / 8 + 1e-5);
}

TEST_P(ApexHeight, FullHoldPeaksAtHOverHeldScale) {
  const double dt = GetParam();
  const CharacterSettings tuning;  // held_gravity_scale 0.5
  const int hold_all_the_way = static_cast<int>(3.0 / dt);
  const JumpRun jump = jump_and_measure(GetParam(), hold_all_the_way);
  const double a = g * tuning.held_gravity_scale;
  const double apex = tuning.jump_height / tuning.held_gravity_scale;  // v0^2 / (2 a) = 2 h
  EXPECT_NEAR(jump.rise, discrete_rise(jump.v0, a, dt), rounding_bound(jump.steps, 3.0));
  EXPECT_GE(jump.rise, apex - jump.v0 * dt / 2 - 1e-5);
  EXPECT_LE(jump.rise, apex - jump.v0 * dt / 2 + a * dt * dt / 8 + 1e-5);
}

TEST_P(ApexHeight, ReleasedAfterATenthOfASecondPeaksAtTheScheduleApex) {
  const double dt = GetParam();
  const CharacterSettings tuning;
  const int hold = window_steps(0.1f, GetParam());
  const JumpRun jump = jump_and_measure(GetParam(), hold);
  // Exact discrete schedule: H steps at g/2, then g.
  const double a_held = g * tuning.held_gravity_scale;
  const double y_release = hold * jump.v0 * dt - a_held * dt * dt * hold * (hold + 1) / 2.0;
  const double v_release = jump.v0 - hold * a_held * dt;
  EXPECT_NEAR(jump.rise, y_release + discrete_rise(v_release, g, dt), rounding_bound(jump.steps, 3.0));
  // Continuous schedule released at t_r = H dt.
  const double t_r = hold * dt;
  const double apex = jump.v0 * t_r - a_held * t_r * t_r / 2 +
                      (jump.v0 - a_held * t_r) * (jump.v0 - a_held * t_r) / (2 * g);
  EXPECT_GE(jump.rise, apex - jump.v0 * dt / 2 - 1e-5);
  EXPECT_LE(jump.rise, apex - jump.v0 * dt / 2 + g * dt * dt / 8 + 1e-5);
  // Lower than the full hold (2 h), higher than a plain jump (h).
  EXPECT_GT(jump.rise, tuning.jump_height);
  EXPECT_LT(jump.rise, 2.0 * tuning.jump_height - jump.v0 * dt);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, ApexHeight,
                         ::testing::Values(1.0f / 30, 1.0f / 60, 1.0f / 120, 1.0f / 240));

TEST(WindowSteps, CountsWholeStepsThatFitTheWindow) {
  EXPECT_EQ(window_steps(0.1f, 1.0f / 60), 6);
  EXPECT_EQ(window_steps(0.1f, 1.0f / 120), 12);
  EXPECT_EQ(window_steps(0.1f, 1.0f / 30), 3);
  EXPECT_EQ(window_steps(0.1f, 1.0f / 144), 14);  // 14.4 steps: the 15th would end after 0.1 s
  EXPECT_EQ(window_steps(0.0f, 1.0f / 60), 0);
}

// ---- coyote time -------------------------------------------------------------------------

namespace {

// Walks right off a ledge (top y = 0, edge x = 0) with nothing below for 10 m. Jump pressed
// (one step) at update `press_step` (or never when < 0). Returns the action per update.
std::vector<CharacterAction> walk_off_ledge(float dt, std::int64_t press_step,
                                            std::int64_t* last_grounded_step) {
  World world(settings_at(dt));
  add_floor(world, -20.0f, 0.0f, 0.0f);
  CharacterDef def;
  def.position = {-3.0f, 0.5f};
  def.settings.extra_jumps = 0;  // only the coyote window can make a jump in the air
  Character character(world, def);
  InputScript script;
  script.set(0, CharacterInput{1.0f, false, false});
  if (press_step >= 0) {
    script.set(press_step, CharacterInput{1.0f, true, false});
    script.set(press_step + 1, CharacterInput{1.0f, false, false});
  }
  std::vector<CharacterAction> actions;
  *last_grounded_step = -1;
  run(world, character, script, static_cast<int>(2.0 / dt), [&](std::int64_t step) {
    actions.push_back(character.last_action());
    if (character.grounded()) *last_grounded_step = step;
  });
  return actions;
}

}  // namespace

class CoyoteWindow : public ::testing::TestWithParam<float> {};

TEST_P(CoyoteWindow, LastStepThatJumpsAndFirstThatDoesNot) {
  const float dt = GetParam();
  const int window = window_steps(CharacterSettings{}.coyote_time, dt);
  std::int64_t last_grounded = -1;
  walk_off_ledge(dt, -1, &last_grounded);
  ASSERT_GT(last_grounded, 0);

  std::int64_t same_ground = -1;
  const std::int64_t last_that_jumps = last_grounded + window;
  const auto jumped = walk_off_ledge(dt, last_that_jumps, &same_ground);
  EXPECT_EQ(same_ground, last_grounded);  // the walk up to the ledge does not depend on the press
  EXPECT_EQ(jumped[static_cast<std::size_t>(last_that_jumps)], CharacterAction::CoyoteJump);

  const std::int64_t first_that_does_not = last_that_jumps + 1;
  const auto missed = walk_off_ledge(dt, first_that_does_not, &same_ground);
  EXPECT_EQ(std::count(missed.begin(), missed.end(), CharacterAction::None),
            static_cast<long>(missed.size()));
  // The window in seconds: the last jump is at most coyote_time after the last grounded step.
  EXPECT_LE(window * dt, CharacterSettings{}.coyote_time + 1e-6);
  EXPECT_GT((window + 1) * dt, CharacterSettings{}.coyote_time);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, CoyoteWindow, ::testing::Values(1.0f / 60, 1.0f / 120, 1.0f / 50));

// ---- jump buffering ----------------------------------------------------------------------

namespace {

// Falls from 1.5 m onto a floor; jump pressed for one step at `press_step` (never if < 0).
std::vector<CharacterAction> fall_and_press(float dt, std::int64_t press_step,
                                            std::int64_t* landing_step) {
  World world(settings_at(dt));
  add_floor(world, -20.0f, 20.0f, 0.0f);
  CharacterDef def;
  def.position = {0.0f, 2.0f};
  def.settings.extra_jumps = 0;  // a press in the air can only be buffered
  Character character(world, def);
  InputScript script;
  if (press_step >= 0) {
    script.set(press_step, CharacterInput{0.0f, true, false});
    script.set(press_step + 1, CharacterInput{});
  }
  std::vector<CharacterAction> actions;
  *landing_step = -1;
  run(world, character, script, static_cast<int>(1.5 / dt), [&](std::int64_t step) {
    actions.push_back(character.last_action());
    if (*landing_step < 0 && (character.grounded() || character.last_action() != CharacterAction::None)) {
      *landing_step = step;
    }
  });
  return actions;
}

}  // namespace

class BufferWindow : public ::testing::TestWithParam<float> {};

TEST_P(BufferWindow, PressUpToTheWindowBeforeLandingJumpsOnLanding) {
  const float dt = GetParam();
  const int window = window_steps(CharacterSettings{}.jump_buffer_time, dt);
  std::int64_t landing = -1;
  fall_and_press(dt, -1, &landing);
  ASSERT_GT(landing, window + 1);

  std::int64_t landing_with_press = -1;
  const auto earliest_that_jumps = fall_and_press(dt, landing - window, &landing_with_press);
  EXPECT_EQ(landing_with_press, landing);
  EXPECT_EQ(earliest_that_jumps[static_cast<std::size_t>(landing)], CharacterAction::GroundJump);

  const auto too_early = fall_and_press(dt, landing - window - 1, &landing_with_press);
  EXPECT_EQ(std::count(too_early.begin(), too_early.end(), CharacterAction::None),
            static_cast<long>(too_early.size()));
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, BufferWindow, ::testing::Values(1.0f / 60, 1.0f / 120, 1.0f / 50));

// ---- extra jumps -------------------------------------------------------------------------

TEST(ExtraJumps, CountIsConfigurableAndRefillsOnLanding) {
  for (int extra : {0, 1, 2, 3}) {
    World world(settings_at(1.0f / 60));
    add_floor(world, -20.0f, 20.0f, 0.0f);
    CharacterDef def;
    def.position = {0.0f, 0.5f};
    def.settings.extra_jumps = extra;
    Character character(world, def);
    // Two rounds: six taps 8 steps apart, then time to land.
    InputScript script;
    for (int round = 0; round < 2; ++round) {
      const int start = 20 + round * 300;
      for (int tap = 0; tap < 6; ++tap) {
        script.set(start + 8 * tap, CharacterInput{0.0f, true, false});
        script.set(start + 8 * tap + 1, CharacterInput{});
      }
    }
    int ground_jumps = 0, air_jumps = 0;
    int air_jumps_first_round = -1;
    run(world, character, script, 600, [&](std::int64_t step) {
      if (character.last_action() == CharacterAction::GroundJump) ++ground_jumps;
      if (character.last_action() == CharacterAction::AirJump) ++air_jumps;
      if (step == 319) air_jumps_first_round = air_jumps;
    });
    EXPECT_EQ(ground_jumps, 2) << "extra_jumps " << extra;
    EXPECT_EQ(air_jumps_first_round, extra) << "extra_jumps " << extra;
    EXPECT_EQ(air_jumps, 2 * extra) << "extra_jumps " << extra;
  }
}

TEST(ExtraJumps, AirJumpSetsTheTakeOffSpeed) {
  World world(settings_at(1.0f / 60));
  add_floor(world, -20.0f, 20.0f, 0.0f);
  CharacterDef def;
  def.position = {0.0f, 0.5f};
  Character character(world, def);
  InputScript script;
  script.set(20, CharacterInput{0.0f, true, false});
  script.set(21, CharacterInput{});
  script.set(60, CharacterInput{0.0f, true, false});  // past the apex: falling
  float vy_after_air_jump = 0.0f;
  run(world, character, script, 70, [&](std::int64_t step) {
    if (step == 60) vy_after_air_jump = world.body(character.body()).linear_velocity.y;
  });
  const double dt = 1.0 / 60;
  // Set to v0, then one step of held gravity.
  EXPECT_NEAR(vy_after_air_jump, character.jump_speed(world) - 0.5 * g * dt, 1e-5);
}

// ---- walls -------------------------------------------------------------------------------

namespace {

struct WallRun {
  std::vector<vec2> velocities;          // after each step
  std::vector<CharacterAction> actions;  // per update
  std::vector<CharacterSupport> supports;
};

// A wall whose left face is at x = 1; the character starts in the air touching it (5 mm
// overlap), presses right (into the wall) throughout, and taps jump at `press_step`.
WallRun slide_and_wall_jump(float dt, std::int64_t press_step, int steps) {
  World world(settings_at(dt));
  add_floor(world, -20.0f, 20.0f, 0.0f);
  add_wall(world, 1.0f, 2.0f, 0.0f, 20.0f);
  CharacterDef def;
  def.position = {1.0f - 0.3f + 0.005f, 8.0f};
  def.settings.extra_jumps = 0;
  Character character(world, def);
  InputScript script;
  script.set(0, CharacterInput{1.0f, false, false});
  script.set(press_step, CharacterInput{1.0f, true, false});
  script.set(press_step + 1, CharacterInput{1.0f, false, false});
  WallRun result;
  run(world, character, script, steps, [&](std::int64_t) {
    result.velocities.push_back(world.body(character.body()).linear_velocity);
    result.actions.push_back(character.last_action());
    result.supports.push_back(character.support());
  });
  return result;
}

}  // namespace

class WallJump : public ::testing::TestWithParam<float> {};

TEST_P(WallJump, SlidesAtTheCapThenJumpsAwayWithTheSetVelocityAndLock) {
  const float dt = GetParam();
  const CharacterSettings tuning;
  const std::int64_t press = static_cast<std::int64_t>(std::lround(1.0 / dt));
  const WallRun wall = slide_and_wall_jump(dt, press, static_cast<int>(press) + 60);

  // Wall slide: the fall speed reaches the cap and stays there exactly.
  const std::size_t before_press = static_cast<std::size_t>(press - 1);
  EXPECT_EQ(wall.supports[before_press], CharacterSupport::WallSlide);
  EXPECT_NEAR(wall.velocities[before_press].y, -tuning.wall_slide_speed, 1e-6);
  EXPECT_NEAR(wall.velocities[before_press].x, 0.0f, 1e-6);

  // The jump: away from the wall (its normal is -x) at the set speed, up at the set speed
  // minus one step of held gravity.
  const std::size_t jump = static_cast<std::size_t>(press);
  EXPECT_EQ(wall.actions[jump], CharacterAction::WallJump);
  EXPECT_FLOAT_EQ(wall.velocities[jump].x, -tuning.wall_jump_velocity.x);
  EXPECT_NEAR(wall.velocities[jump].y,
              tuning.wall_jump_velocity.y - tuning.held_gravity_scale * g * dt, 1e-5);

  // The lock: input (still pressing into the wall) is ignored for the lock window.
  const int lock = window_steps(tuning.wall_jump_lock_time, dt);
  for (int k = 1; k <= lock; ++k) {
    EXPECT_FLOAT_EQ(wall.velocities[jump + k].x, -tuning.wall_jump_velocity.x) << "step " << k;
  }
  EXPECT_NEAR(wall.velocities[jump + lock + 1].x,
              -tuning.wall_jump_velocity.x + tuning.air_acceleration * dt, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, WallJump, ::testing::Values(1.0f / 60, 1.0f / 120));

// ---- ceiling -----------------------------------------------------------------------------

TEST(Ceiling, StopsTheRiseAndEndsTheHeldPhase) {
  const float dt = 1.0f / 60;
  World world(settings_at(dt));
  add_floor(world, -20.0f, 20.0f, 0.0f);
  add_wall(world, -5.0f, 5.0f, 2.0f, 3.0f);  // ceiling underside at y = 2
  CharacterDef def;
  def.position = {0.0f, 0.5f};
  Character character(world, def);
  InputScript script;
  script.set(20, CharacterInput{0.0f, true, false});  // held: would rise 2.4 m
  double highest_top = 0.0;
  std::int64_t first_ceiling_update = -1;
  float scale_after_hit = 0.0f;
  run(world, character, script, 120, [&](std::int64_t step) {
    const BodyView body = world.body(character.body());
    highest_top = std::max(highest_top, static_cast<double>(body.transform.position.y) + 0.5);
    if (first_ceiling_update < 0 && step > 20 && body.linear_velocity.y <= 0.0f) {
      first_ceiling_update = step;
    }
    if (first_ceiling_update >= 0 && step == first_ceiling_update + 1) scale_after_hit = character.gravity_scale();
  });
  // The engine detects the overlap one step late: the top may enter by one step's travel.
  // Speed there: v^2 = v0^2 - 2 (g/2) (2 m - 1 m), the head starting at 1 m.
  const double v0 = character.jump_speed(world);
  const double speed_at_ceiling = std::sqrt(v0 * v0 - 2.0 * (0.5 * g) * 1.0);
  EXPECT_LT(highest_top, 2.0 + speed_at_ceiling * dt);
  EXPECT_GT(highest_top, 2.0 - 0.02);
  EXPECT_EQ(scale_after_hit, 1.0f);
}

// Projectile motion against the exact answer, with the integrators' known errors.
//
// With constant acceleration -g, n steps of dt (t = n dt):
//   semi-implicit Euler: y_n = y0 + v0 t - g t^2 / 2 - g t dt / 2   (velocity first)
//   explicit Euler:      y_n = y0 + v0 t - g t^2 / 2 + g t dt / 2   (position first)
//   both:                v_n = v0 - g t (exact)
// so each integrator's discrete answer is known in closed form; the only tolerance left is
// float rounding: each step adds at most one rounding of |y| (2^-24 relative) to the position.
#include "core/world.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace impulse2d;

namespace {

struct Flight {
  float x, y, vx, vy;
};

Flight fly(Integrator integrator, float dt, int steps, vec2 v0) {
  // One sub-step of the chosen integrator (the soft step always integrates semi-implicitly,
  // in sub-steps: SubstepsShrinkTheErrorByTheirCount below).
  WorldSettings settings = settings_for(SolverMethod::Accumulated);
  settings.time_step = dt;
  settings.integrator = integrator;
  settings.gravity = {0.0f, -9.81f};
  World world(settings);
  BodyDef def;
  def.position = {0.0f, 100.0f};
  def.linear_velocity = v0;
  const BodyId body = world.create_body(def, make_circle(0.25f));
  for (int i = 0; i < steps; ++i) world.step();
  const BodyView b = world.body(body);
  return {b.transform.position.x, b.transform.position.y, b.linear_velocity.x, b.linear_velocity.y};
}

// Accumulated rounding: one half-ulp-scale error per step on values of size `scale`.
double rounding_bound(int steps, double scale) { return steps * scale * std::ldexp(1.0, -23); }

}  // namespace

class Projectile : public ::testing::TestWithParam<float> {};

TEST_P(Projectile, SemiImplicitEulerMatchesItsClosedFormAndErrsByHalfGTDt) {
  const float dt = GetParam();
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  const double t = steps * static_cast<double>(dt);
  const double g = 9.81, y0 = 100.0, v0x = 3.0, v0y = 12.0;
  const Flight flight = fly(Integrator::SemiImplicitEuler, dt, steps, {3.0f, 12.0f});
  const double exact = y0 + v0y * t - g * t * t / 2;
  const double discrete = exact - g * t * dt / 2;
  EXPECT_NEAR(flight.y, discrete, rounding_bound(steps, 130.0));
  EXPECT_NEAR(flight.y - exact, -g * t * dt / 2, rounding_bound(steps, 130.0));
  EXPECT_NEAR(flight.vy, v0y - g * t, rounding_bound(steps, 20.0));
  EXPECT_NEAR(flight.x, v0x * t, rounding_bound(steps, 10.0));
  EXPECT_NEAR(flight.vx, v0x, 1e-6);
}

TEST_P(Projectile, ExplicitEulerErrsTheOtherWay) {
  const float dt = GetParam();
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  const double t = steps * static_cast<double>(dt);
  const double g = 9.81, y0 = 100.0, v0y = 12.0;
  const Flight flight = fly(Integrator::ExplicitEuler, dt, steps, {0.0f, 12.0f});
  const double exact = y0 + v0y * t - g * t * t / 2;
  EXPECT_NEAR(flight.y - exact, +g * t * dt / 2, rounding_bound(steps, 130.0));
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, Projectile, ::testing::Values(1.0f / 30, 1.0f / 60, 1.0f / 240));

TEST(Projectile, SubstepsShrinkTheErrorByTheirCount) {
  // Four substeps of dt/4 are the same integrator at dt/4: the error g t dt / 2 shrinks 4x.
  WorldSettings settings;
  settings.substeps = 4;
  World world(settings);
  BodyDef def;
  def.position = {0.0f, 100.0f};
  const BodyId body = world.create_body(def, make_circle(0.25f));
  for (int i = 0; i < 60; ++i) world.step();
  const double t = 1.0, dt = 1.0 / 60 / 4, g = 9.81;
  EXPECT_NEAR(world.body(body).transform.position.y - (100.0 - g * t * t / 2), -g * t * dt / 2,
              rounding_bound(240, 110.0));
}

TEST(Projectile, GravityScaleAndDampingFollowTheirFormulas) {
  // The formulas of one step of dt (damping is applied per sub-step).
  WorldSettings settings = settings_for(SolverMethod::Accumulated);
  World world(settings);
  BodyDef def;
  def.gravity_scale = 0.5f;
  def.linear_damping = 2.0f;
  const BodyId body = world.create_body(def, make_circle(0.25f));
  world.step();
  const double dt = settings.time_step;
  // v = (0 + g * 0.5 * dt) / (1 + dt * damping)
  EXPECT_NEAR(world.body(body).linear_velocity.y, -9.81 * 0.5 * dt / (1 + dt * 2.0), 1e-6);
}

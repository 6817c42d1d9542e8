// Head-on collisions on a line: v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2); momentum and, for
// e = 1, kinetic energy are kept. One contact point along the line of centres makes the
// impulse exact, so the tolerance is float rounding of the velocities (a few ulps).
#include "core/world.h"

#include <gtest/gtest.h>

using namespace impulse2d;

namespace {
struct Outcome {
  float m1, m2, v1, v2;
};

Outcome collide_head_on(float radius1, float radius2, float v1, float v2, float restitution,
                        SolverMethod solver) {
  WorldSettings settings;
  settings.gravity = {0, 0};
  settings.restitution_threshold = 0.0f;
  settings.solver = solver;
  World world(settings);
  const Material material{"Elastic", 1.0f, restitution, 0.0f, 0.0f};
  BodyDef def;
  def.material = material;
  def.position = {-radius1 - 0.001f, 0};
  def.linear_velocity = {v1, 0};
  const BodyId a = world.create_body(def, make_circle(radius1));
  def.position = {radius2 + 0.001f, 0};
  def.linear_velocity = {v2, 0};
  const BodyId b = world.create_body(def, make_circle(radius2));
  for (int i = 0; i < 10; ++i) world.step();
  return {world.body(a).mass, world.body(b).mass, world.body(a).linear_velocity.x,
          world.body(b).linear_velocity.x};
}
}  // namespace

TEST(Collision1D, ElasticKeepsMomentumAndEnergyAndMatchesTheFormula) {
  for (SolverMethod solver : {SolverMethod::Accumulated, SolverMethod::PerIteration}) {
    const float v1 = 3.0f, v2 = -1.0f;
    const Outcome out = collide_head_on(0.5f, 0.3f, v1, v2, 1.0f, solver);
    const double m1 = out.m1, m2 = out.m2;
    const double expected1 = ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2);
    const double expected2 = ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2);
    EXPECT_NEAR(out.v1, expected1, 1e-5);
    EXPECT_NEAR(out.v2, expected2, 1e-5);
    const double momentum_before = m1 * v1 + m2 * v2;
    const double momentum_after = m1 * out.v1 + m2 * out.v2;
    EXPECT_NEAR(momentum_after, momentum_before, 1e-5 * (m1 + m2));
    const double energy_before = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2);
    const double energy_after = 0.5 * (m1 * out.v1 * out.v1 + m2 * out.v2 * out.v2);
    EXPECT_NEAR(energy_after, energy_before, 1e-5 * energy_before);
  }
}

TEST(Collision1D, InelasticEndsWithACommonVelocity) {
  const Outcome out = collide_head_on(0.5f, 0.5f, 2.0f, 0.0f, 0.0f, SolverMethod::Accumulated);
  EXPECT_NEAR(out.v1, 1.0f, 1e-5f);
  EXPECT_NEAR(out.v2, 1.0f, 1e-5f);
}

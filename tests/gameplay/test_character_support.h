#pragma once
// Shared set-up of the character suites: a world at a chosen time step with static boxes and
// slopes, a character, and a loop that drives it with an input script.
#include "gameplay/character.h"
#include "gameplay/one_way_platform.h"
#include "core/world.h"

#include <cmath>
#include <functional>

namespace impulse2d::character_test {

constexpr double g = 9.81;  // m/s^2, the world's default gravity

/// Ground material: no bounce, ordinary friction.
inline Material ground_material() { return Material{"Ground", 0.0f, 0.0f, 0.6f, 0.4f}; }

/// A world at time step `dt` on the accumulated solver at one sub-step, which the character
/// controller is tuned for (its scenes pick it), with default settings otherwise.
inline WorldSettings settings_at(float dt) {
  WorldSettings settings = settings_for(SolverMethod::Accumulated);
  settings.time_step = dt;
  return settings;
}

/// A static axis-aligned box whose top face is at `top` (metres), spanning x in [left, right].
inline BodyId add_floor(World& world, float left, float right, float top, float thickness = 1.0f) {
  BodyDef def;
  def.type = BodyType::Static;
  def.position = {0.5f * (left + right), top - 0.5f * thickness};
  def.material = ground_material();
  return world.create_body(def, make_box({0.5f * (right - left), 0.5f * thickness}));
}

/// A static wall: a box spanning x in [left, right] and y in [bottom, top].
inline BodyId add_wall(World& world, float left, float right, float bottom, float top) {
  BodyDef def;
  def.type = BodyType::Static;
  def.position = {0.5f * (left + right), 0.5f * (bottom + top)};
  def.material = ground_material();
  return world.create_body(def, make_box({0.5f * (right - left), 0.5f * (top - bottom)}));
}

/// A static right triangle rising from (x0, y0) to the right at `angle` radians over `run`
/// metres of x. Returns the body; its surface is y = y0 + (x - x0) tan(angle).
inline BodyId add_slope(World& world, float x0, float y0, float run, float angle,
                        const Material& material = ground_material()) {
  const float rise = run * std::tan(angle);
  const vec2 corners[3] = {{x0, y0}, {x0 + run, y0}, {x0 + run, y0 + rise}};
  vec2 centroid;
  const Shape shape = make_polygon(corners, 3, &centroid);
  BodyDef def;
  def.type = BodyType::Static;
  def.position = centroid;
  def.material = material;
  return world.create_body(def, shape);
}

/// Runs `steps` steps: `before_update(step)` (move platforms), character.update with the
/// script's input, world.step(), then `after_step(step)` to record.
inline void run(World& world, Character& character, const InputScript& script, int steps,
                const std::function<void(std::int64_t)>& after_step,
                const std::function<void(std::int64_t)>& before_update = nullptr) {
  for (int i = 0; i < steps; ++i) {
    const std::int64_t step = world.step_count();
    if (before_update) before_update(step);
    character.update(world, script.at(step));
    world.step();
    if (after_step) after_step(step);
  }
}

/// Discrete apex above the start of n semi-implicit Euler steps from speed v under constant
/// deceleration a: positions y_n = n v dt - a dt^2 n (n + 1) / 2 peak at n = floor(v / (a dt)).
inline double discrete_rise(double v, double a, double dt) {
  const double n = std::floor(v / (a * dt));
  return n * v * dt - a * dt * dt * n * (n + 1.0) / 2.0;
}

}  // namespace impulse2d::character_test

#pragma once
// Bounce apex heights h_k = e^(2k) h0 (restitution threshold off), shared by the solver suites.
//
// Error model per bounce, for impact speed v_i = e^(i-1) sqrt(2 g h0) and step dt:
//  - the contact is found up to one step late, so the reflected speed is off by <= g dt,
//    which moves the apex by <= v_i g dt / g = v_i dt;
//  - the ball can be up to v_i dt inside the ground when it reflects, and position
//    correction removes at most that overlap again: <= 2 v_i dt of height;
//  - an error at bounce i is scaled by e^2 at every later bounce;
//  - the apex is sampled at step times: <= g dt^2 (semi-implicit Euler's bias included).
// So |h_k - e^(2k) h0| <= sum_i e^(2(k-i)) 3 v_i dt + g dt^2.
#include "core/world.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace impulse2d::bounce_test {

/// Drops a ball (radius 0.25 m, restitution e) from `drop_height` metres above a floor of the
/// same restitution, with `settings` but no friction and no restitution threshold, and returns
/// the heights (metres above the floor) of its first `bounces` apexes.
/// The apexes of a height sampled once a step: the highest sample of each rise, recorded when
/// the vertical velocity stops being upward.
class ApexTracker {
 public:
  /// Takes one step's `height` (m) and vertical velocity (m/s).
  void sample(double height, float vertical_velocity) {
    if (vertical_velocity > 0.0f) {
      rising_ = true;
      highest_ = std::max(highest_, height);
    } else if (rising_) {
      apexes_.push_back(std::max(highest_, height));
      rising_ = false;
      highest_ = -1.0;
    }
  }
  /// The apexes so far, in order (m).
  const std::vector<double>& apexes() const { return apexes_; }

 private:
  std::vector<double> apexes_;
  double highest_ = -1.0;
  bool rising_ = false;
};

inline std::vector<double> bounce_apexes(WorldSettings settings, float e, float drop_height,
                                         int bounces) {
  settings.restitution_threshold = 0.0f;
  settings.enable_friction = false;
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = Material{"Floor", 0.0f, e, 0.0f, 0.0f};
  ground.position = {0.0f, -1.0f};
  world.create_body(ground, make_box({5.0f, 1.0f}));  // top face at y = 0
  const float radius = 0.25f;
  BodyDef ball;
  ball.material = Material{"Ball", 1.0f, e, 0.0f, 0.0f};
  ball.position = {0.0f, radius + drop_height};
  const BodyId id = world.create_body(ball, make_circle(radius));

  ApexTracker tracker;
  for (int step = 0; step < 200000 && static_cast<int>(tracker.apexes().size()) < bounces; ++step) {
    world.step();
    const BodyView body = world.body(id);
    tracker.sample(body.transform.position.y - radius, body.linear_velocity.y);
  }
  return tracker.apexes();
}

/// The error bound above for apex k (1-based) of a drop from h0 with restitution e, gravity g
/// and step dt.
inline double bounce_apex_tolerance(double e, double h0, double g, double dt, int k) {
  double tolerance = g * dt * dt;
  for (int i = 1; i <= k; ++i) {
    const double impact_speed = std::pow(e, i - 1) * std::sqrt(2 * g * h0);
    tolerance += std::pow(e, 2 * (k - i)) * 3 * impact_speed * dt;
  }
  return tolerance;
}

}  // namespace impulse2d::bounce_test

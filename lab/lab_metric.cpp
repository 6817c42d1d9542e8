/// @file lab_metric.cpp
#include "lab/lab_metric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse2d::lab {
namespace {

constexpr double infinite_error = std::numeric_limits<double>::infinity();

bool finite_state(const BodyState& state) {
  return std::isfinite(state.position.x) && std::isfinite(state.position.y) &&
         std::isfinite(state.velocity.x) && std::isfinite(state.velocity.y) &&
         std::isfinite(state.angle) && std::isfinite(state.angular_velocity);
}

double sign_of(double value) { return value < 0.0 ? -1.0 : 1.0; }

/// Base for trackers: turns any non-finite body into an infinite error.
class TrackerBase : public MetricTracker {
 public:
  void observe(double time, const std::vector<BodyState>& states) final {
    if (diverged_) return;
    for (const BodyState& state : states) {
      if (!finite_state(state)) {
        diverged_ = true;
        return;
      }
    }
    observe_finite(time, states);
  }
  double error() const final { return diverged_ ? infinite_error : finite_error(); }

 protected:
  virtual void observe_finite(double time, const std::vector<BodyState>& states) = 0;
  virtual double finite_error() const = 0;

 private:
  bool diverged_ = false;
};

class FreeFlightTracker : public TrackerBase {
 public:
  FreeFlightTracker(int body, const BodyState& start, vec2 gravity)
      : body_(body), start_(start), gravity_(gravity) {}
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    const double x = start_.position.x + start_.velocity.x * time + 0.5 * gravity_.x * time * time;
    const double y = start_.position.y + start_.velocity.y * time + 0.5 * gravity_.y * time * time;
    const vec2 at = states[static_cast<std::size_t>(body_)].position;
    worst_ = std::max(worst_, std::hypot(at.x - x, at.y - y));
  }
  double finite_error() const override { return worst_; }

 private:
  int body_;
  BodyState start_;
  vec2 gravity_;
  double worst_ = 0.0;
};

/// Distance travelled along a surface by a block starting at speed `v0` (m/s) with gravity
/// components `along` (m/s^2, along the surface) and `normal` (> 0, into it), under Coulomb
/// friction mu_s / mu_d: holds, slides, or decelerates, stops and then holds or slides back.
double block_travel(double time, double v0, double along, double normal, double mu_s,
                    double mu_d) {
  if (std::fabs(v0) < 1e-9) {
    if (std::fabs(along) <= mu_s * normal) return 0.0;
    const double acceleration = along - sign_of(along) * mu_d * normal;
    return 0.5 * acceleration * time * time;
  }
  const double acceleration = along - sign_of(v0) * mu_d * normal;
  if (acceleration * v0 < 0.0) {
    const double stop_time = -v0 / acceleration;
    if (time > stop_time) {
      const double stop_distance = v0 * stop_time + 0.5 * acceleration * stop_time * stop_time;
      return stop_distance + block_travel(time - stop_time, 0.0, along, normal, mu_s, mu_d);
    }
  }
  return v0 * time + 0.5 * acceleration * time * time;
}

class SlopeMotionTracker : public TrackerBase {
 public:
  SlopeMotionTracker(const MetricSpec& spec, const LabSimulation& simulation,
                     const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), rolls_(spec.rolls) {
    const BodyState& surface = start.at(static_cast<std::size_t>(spec.surface));
    const float angle = surface.angle;
    tangent_ = {std::cos(angle), std::sin(angle)};
    const vec2 normal{-std::sin(angle), std::cos(angle)};
    const vec2 gravity = simulation.gravity();
    along_ = gravity.x * tangent_.x + gravity.y * tangent_.y;
    normal_ = -(gravity.x * normal.x + gravity.y * normal.y);
    const BodyState& body = start.at(static_cast<std::size_t>(body_));
    origin_ = body.position;
    v0_ = body.velocity.x * tangent_.x + body.velocity.y * tangent_.y;
    coefficients_ = simulation.coefficients(body_, spec.surface);
  }
  /// Exact distance along the surface after `time` seconds, m.
  double exact_travel(double time) const {
    const double mu_s = coefficients_.static_friction;
    const double mu_d = coefficients_.dynamic_friction;
    if (!rolls_) return block_travel(time, v0_, along_, normal_, mu_s, mu_d);
    const bool rolling = std::fabs(along_) <= 3.0 * mu_s * normal_;
    const double acceleration =
        rolling ? 2.0 / 3.0 * along_ : along_ - sign_of(along_) * mu_d * normal_;
    return v0_ * time + 0.5 * acceleration * time * time;
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    const vec2 at = states[static_cast<std::size_t>(body_)].position;
    const double travel = (at.x - origin_.x) * tangent_.x + (at.y - origin_.y) * tangent_.y;
    worst_ = std::max(worst_, std::fabs(travel - exact_travel(time)));
  }
  double finite_error() const override { return worst_; }

 private:
  int body_;
  bool rolls_;
  vec2 tangent_{1.0f, 0.0f};
  double along_ = 0.0;
  double normal_ = 0.0;
  vec2 origin_{0.0f, 0.0f};
  double v0_ = 0.0;
  ContactCoefficients coefficients_;
  double worst_ = 0.0;
};

class BounceApexTracker : public TrackerBase {
 public:
  BounceApexTracker(const MetricSpec& spec, const LabSimulation& simulation,
                    const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), rest_height_(spec.rest_height) {
    const double e = simulation.coefficients(spec.bodies.at(0), spec.bodies.at(1)).restitution;
    const double h0 = start.at(static_cast<std::size_t>(body_)).position.y - rest_height_;
    for (int k = 1; k <= spec.apex_count; ++k) exact_.push_back(std::pow(e, 2.0 * k) * h0);
    previous_ = start.at(static_cast<std::size_t>(body_));
  }
  void observe_finite(double, const std::vector<BodyState>& states) override {
    const BodyState& now = states[static_cast<std::size_t>(body_)];
    if (previous_.velocity.y > 0.0f && now.velocity.y <= 0.0f && apexes_.size() < exact_.size()) {
      apexes_.push_back(std::max(previous_.position.y, now.position.y) - rest_height_);
    }
    previous_ = now;
  }
  double finite_error() const override {
    double worst = 0.0;
    for (std::size_t k = 0; k < exact_.size(); ++k) {
      const double measured = k < apexes_.size() ? apexes_[k] : 0.0;
      worst = std::max(worst, std::fabs(measured - exact_[k]));
    }
    return worst;
  }

 private:
  int body_;
  double rest_height_;
  std::vector<double> exact_;
  std::vector<double> apexes_;
  BodyState previous_;
};

class Collision1dTracker : public TrackerBase {
 public:
  Collision1dTracker(const MetricSpec& spec, const LabSimulation& simulation,
                     const std::vector<BodyState>& start)
      : first_(spec.bodies.at(0)), second_(spec.bodies.at(1)) {
    const BodyState& a = start.at(static_cast<std::size_t>(first_));
    const BodyState& b = start.at(static_cast<std::size_t>(second_));
    const double e = simulation.coefficients(first_, second_).restitution;
    const double m1 = a.mass, m2 = b.mass, u1 = a.velocity.x, u2 = b.velocity.x;
    const double momentum = m1 * u1 + m2 * u2;
    exact_first_ = (momentum - m2 * e * (u1 - u2)) / (m1 + m2);
    exact_second_ = (momentum + m1 * e * (u1 - u2)) / (m1 + m2);
    approach_speed_ = std::fabs(u1 - u2);
  }
  void observe_finite(double, const std::vector<BodyState>& states) override {
    const BodyState& a = states[static_cast<std::size_t>(first_)];
    const BodyState& b = states[static_cast<std::size_t>(second_)];
    error_ = std::max(std::hypot(a.velocity.x - exact_first_, a.velocity.y),
                      std::hypot(b.velocity.x - exact_second_, b.velocity.y)) /
             approach_speed_;
  }
  double finite_error() const override { return error_; }

 private:
  int first_, second_;
  double exact_first_ = 0.0, exact_second_ = 0.0, approach_speed_ = 1.0;
  double error_ = 0.0;
};

class CradleTracker : public TrackerBase {
 public:
  CradleTracker(const MetricSpec& spec, const std::vector<BodyState>& start)
      : balls_(spec.bodies) {
    speed_ = start.at(static_cast<std::size_t>(balls_.front())).velocity.x;
  }
  void observe_finite(double, const std::vector<BodyState>& states) override {
    error_ = 0.0;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const vec2 v = states[static_cast<std::size_t>(balls_[i])].velocity;
      const double exact = i + 1 == balls_.size() ? speed_ : 0.0;
      error_ = std::max(error_, std::hypot(v.x - exact, v.y) / std::fabs(speed_));
    }
  }
  double finite_error() const override { return error_; }

 private:
  std::vector<int> balls_;
  double speed_ = 1.0;
  double error_ = 0.0;
};

double mechanical_energy(const std::vector<BodyState>& states, vec2 gravity) {
  double energy = 0.0;
  for (const BodyState& state : states) {
    if (!state.dynamic) continue;
    const double speed_squared = static_cast<double>(state.velocity.x) * state.velocity.x +
                                 static_cast<double>(state.velocity.y) * state.velocity.y;
    energy += 0.5 * state.mass * speed_squared +
              0.5 * state.inertia * state.angular_velocity * state.angular_velocity -
              state.mass * (gravity.x * state.position.x + gravity.y * state.position.y);
  }
  return energy;
}

class EnergyTracker : public TrackerBase {
 public:
  EnergyTracker(vec2 gravity, const std::vector<BodyState>& start)
      : gravity_(gravity), initial_(mechanical_energy(start, gravity)) {}
  void observe_finite(double, const std::vector<BodyState>& states) override {
    const double change = std::fabs(mechanical_energy(states, gravity_) - initial_);
    worst_ = std::max(worst_, 100.0 * change / std::fabs(initial_));
  }
  double finite_error() const override { return worst_; }

 private:
  vec2 gravity_;
  double initial_;
  double worst_ = 0.0;
};

class RestTracker : public TrackerBase {
 public:
  RestTracker(const MetricSpec& spec, const std::vector<BodyState>& start) : start_(start) {
    bodies_ = spec.bodies;
    if (bodies_.empty()) {
      for (std::size_t i = 0; i < start.size(); ++i) {
        if (start[i].dynamic) bodies_.push_back(static_cast<int>(i));
      }
    }
  }
  void observe_finite(double, const std::vector<BodyState>& states) override {
    error_ = 0.0;
    for (const int body : bodies_) {
      const vec2 now = states[static_cast<std::size_t>(body)].position;
      const vec2 was = start_[static_cast<std::size_t>(body)].position;
      error_ = std::max(error_, static_cast<double>(std::hypot(now.x - was.x, now.y - was.y)));
    }
  }
  double finite_error() const override { return error_; }

 private:
  std::vector<BodyState> start_;
  std::vector<int> bodies_;
  double error_ = 0.0;
};

class TunnelTracker : public TrackerBase {
 public:
  TunnelTracker(const MetricSpec& spec, const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), wall_(start.at(static_cast<std::size_t>(spec.surface)).position) {
    const vec2 velocity = start.at(static_cast<std::size_t>(body_)).velocity;
    const double speed = std::hypot(velocity.x, velocity.y);
    direction_ = speed > 0.0 ? vec2{static_cast<float>(velocity.x / speed),
                                    static_cast<float>(velocity.y / speed)}
                             : vec2{1.0f, 0.0f};
  }
  void observe_finite(double, const std::vector<BodyState>& states) override {
    const vec2 at = states[static_cast<std::size_t>(body_)].position;
    beyond_ = std::max(0.0, static_cast<double>((at.x - wall_.x) * direction_.x +
                                                (at.y - wall_.y) * direction_.y));
  }
  double finite_error() const override { return beyond_; }

 private:
  int body_;
  vec2 wall_;
  vec2 direction_{1.0f, 0.0f};
  double beyond_ = 0.0;
};

class PeakSpeedTracker : public TrackerBase {
 public:
  void observe_finite(double, const std::vector<BodyState>& states) override {
    for (const BodyState& state : states) {
      if (state.dynamic) peak_ = std::max(peak_, static_cast<double>(std::hypot(state.velocity.x, state.velocity.y)));
    }
  }
  double finite_error() const override { return peak_; }

 private:
  double peak_ = 0.0;
};

}  // namespace

std::unique_ptr<MetricTracker> make_metric_tracker(const MetricSpec& spec,
                                                   const LabSimulation& simulation) {
  std::vector<BodyState> start;
  simulation.read_states(start);
  switch (spec.kind) {
    case MetricKind::FreeFlight:
      return std::make_unique<FreeFlightTracker>(spec.bodies.at(0),
                                                 start.at(static_cast<std::size_t>(spec.bodies.at(0))),
                                                 simulation.gravity());
    case MetricKind::SlopeMotion:
      return std::make_unique<SlopeMotionTracker>(spec, simulation, start);
    case MetricKind::BounceApexes:
      return std::make_unique<BounceApexTracker>(spec, simulation, start);
    case MetricKind::Collision1d:
      return std::make_unique<Collision1dTracker>(spec, simulation, start);
    case MetricKind::Cradle:
      return std::make_unique<CradleTracker>(spec, start);
    case MetricKind::Energy:
      return std::make_unique<EnergyTracker>(simulation.gravity(), start);
    case MetricKind::Rest:
      return std::make_unique<RestTracker>(spec, start);
    case MetricKind::Tunnel:
      return std::make_unique<TunnelTracker>(spec, start);
    case MetricKind::PeakSpeed:
      return std::make_unique<PeakSpeedTracker>();
  }
  return nullptr;
}

}  // namespace impulse2d::lab

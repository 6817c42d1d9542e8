/// @file lab_metric.cpp
#include "lab/lab_metric.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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

/// The exact acceleration along a surface (m/s^2) of a body starting at `v0` with gravity
/// components `along` and `normal` (into the surface): a rolling disc 2/3 along while
/// mu_s >= |along| / (3 normal), else (and for a block) Coulomb sliding; a block at rest holds
/// (0) while |along| <= mu_s normal. Valid until a decelerating block stops.
double surface_acceleration(bool rolls, double v0, double along, double normal,
                            const ContactCoefficients& coefficients) {
  const double mu_s = coefficients.static_friction;
  const double mu_d = coefficients.dynamic_friction;
  if (rolls) {
    if (std::fabs(along) <= 3.0 * mu_s * normal) return 2.0 / 3.0 * along;
    return along - sign_of(along) * mu_d * normal;
  }
  if (std::fabs(v0) < 1e-9) {
    if (std::fabs(along) <= mu_s * normal) return 0.0;
    return along - sign_of(along) * mu_d * normal;
  }
  return along - sign_of(v0) * mu_d * normal;
}

/// A body riding a flat (chained) surface: see `MetricKind::SurfaceRide`.
class SurfaceRideTracker : public TrackerBase {
 public:
  SurfaceRideTracker(const MetricSpec& spec, const LabSimulation& simulation,
                     const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), measure_(spec.measure), after_(spec.after) {
    const float angle = start.at(static_cast<std::size_t>(spec.surface)).angle;
    tangent_ = {std::cos(angle), std::sin(angle)};
    normal_ = {-std::sin(angle), std::cos(angle)};
    const vec2 gravity = simulation.gravity();
    const double along = dot(gravity, tangent_);
    const double into = -dot(gravity, normal_);
    v0_ = dot(start.at(static_cast<std::size_t>(body_)).velocity, tangent_);
    exact_acceleration_ = surface_acceleration(spec.rolls, v0_, along, into,
                                               simulation.coefficients(body_, spec.surface));
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    const BodyState& state = states[static_cast<std::size_t>(body_)];
    if (measure_ != RideMeasure::Acceleration && time < after_ - 1e-9) return;
    switch (measure_) {
      case RideMeasure::NormalSpeed:
        worst_ = std::max(worst_, std::fabs(dot(state.velocity, normal_)));
        break;
      case RideMeasure::AngularSpeed:
        worst_ = std::max(worst_, std::fabs(static_cast<double>(state.angular_velocity)));
        break;
      case RideMeasure::Acceleration: {
        const double mean = time > 0.0 ? (dot(state.velocity, tangent_) - v0_) / time : 0.0;
        worst_ = 100.0 * std::fabs(mean - exact_acceleration_) /
                 std::max(std::fabs(exact_acceleration_), 1e-9);
        break;
      }
    }
  }
  double finite_error() const override { return worst_; }

 private:
  static double dot(vec2 a, vec2 b) {
    return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y;
  }
  int body_;
  RideMeasure measure_;
  double after_ = 0.0;
  vec2 tangent_{1.0f, 0.0f};
  vec2 normal_{0.0f, 1.0f};
  double v0_ = 0.0;
  double exact_acceleration_ = 0.0;
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

/// The times (s) at which a sampled quantity changes sign, interpolated linearly between steps.
class SignChanges {
 public:
  void add(double time, double value) {
    if (has_previous_ && ((previous_value_ < 0.0 && value >= 0.0) || (previous_value_ > 0.0 && value <= 0.0))) {
      const double fraction = previous_value_ / (previous_value_ - value);
      times_.push_back(previous_time_ + fraction * (time - previous_time_));
    }
    // A sample exactly 0 is a crossing already counted (or the start): the next sign decides.
    if (value != 0.0 || !has_previous_) {
      previous_time_ = time;
      previous_value_ = value;
      has_previous_ = true;
    }
  }
  /// Twice the mean time between successive sign changes (a full period of an oscillation
  /// that changes sign twice per period), or 0 with fewer than two.
  double period() const {
    if (times_.size() < 2) return 0.0;
    return 2.0 * (times_.back() - times_.front()) / static_cast<double>(times_.size() - 1);
  }

 private:
  std::vector<double> times_;
  double previous_time_ = 0.0;
  double previous_value_ = 0.0;
  bool has_previous_ = false;
};

/// The relative error of a measured period, percent; 100 when nothing was measured.
double period_error_percent(double measured, double exact) {
  if (measured <= 0.0) return 100.0;
  return 100.0 * std::fabs(measured - exact) / exact;
}

const LabJoint& metric_joint(const MetricSpec& spec, const LabSimulation& simulation) {
  const std::vector<LabJoint>& joints = simulation.joints();
  const int index = spec.joints.at(0);
  if (index < 0 || static_cast<std::size_t>(index) >= joints.size()) {
    throw std::runtime_error("the metric's joint " + std::to_string(index) +
                             " is not among the run's joints");
  }
  return joints[static_cast<std::size_t>(index)];
}

double cross(vec2 a, vec2 b) { return static_cast<double>(a.x) * b.y - static_cast<double>(a.y) * b.x; }
double dot(vec2 a, vec2 b) { return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y; }

/// The velocity of the body-frame point `local` of a body in `state`, m/s.
vec2 point_velocity(const BodyState& state, vec2 local) {
  const vec2 arm = world_point(state, local) - state.position;
  return {state.velocity.x - state.angular_velocity * arm.y,
          state.velocity.y + state.angular_velocity * arm.x};
}

class PendulumTracker : public TrackerBase {
 public:
  PendulumTracker(const MetricSpec& spec, const LabSimulation& simulation,
                  const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), joint_(metric_joint(spec, simulation)) {
    const vec2 gravity = simulation.gravity();
    const double g = std::hypot(gravity.x, gravity.y);
    down_ = gravity / static_cast<float>(g);
    const BodyState& bob = start.at(static_cast<std::size_t>(body_));
    const vec2 pivot = world_point(start.at(static_cast<std::size_t>(joint_.body_a)), joint_.local_anchor_a);
    const vec2 arm = bob.position - pivot;
    const double d = std::hypot(arm.x, arm.y);
    const double theta0 = std::fabs(std::atan2(cross(down_, arm), dot(down_, arm)));
    // A hinge turns the bob with the pendulum; a distance joint (anchored at the bob's centre)
    // leaves its spin alone, so only m d^2 swings.
    const double inertia = joint_.spec.type == JointType::Revolute ? bob.inertia : 0.0;
    const double length = (inertia + bob.mass * d * d) / (bob.mass * d);
    exact_period_ = 4.0 * std::sqrt(length / g) * elliptic_k(std::sin(theta0 / 2.0));
  }
  /// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))), to double precision.
  static double elliptic_k(double k) {
    double a = 1.0, b = std::sqrt(1.0 - k * k);
    for (int i = 0; i < 40 && std::fabs(a - b) > 1e-15 * a; ++i) {
      const double next = 0.5 * (a + b);
      b = std::sqrt(a * b);
      a = next;
    }
    return 3.14159265358979323846 / (2.0 * a);
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    const vec2 pivot = world_point(states[static_cast<std::size_t>(joint_.body_a)], joint_.local_anchor_a);
    const vec2 arm = states[static_cast<std::size_t>(body_)].position - pivot;
    crossings_.add(time, std::atan2(cross(down_, arm), dot(down_, arm)));
  }
  double finite_error() const override {
    return period_error_percent(crossings_.period(), exact_period_);
  }
  double exact_period() const { return exact_period_; }

 private:
  int body_;
  LabJoint joint_;
  vec2 down_{0.0f, -1.0f};
  double exact_period_ = 1.0;
  SignChanges crossings_;
};

class SpringFrequencyTracker : public TrackerBase {
 public:
  SpringFrequencyTracker(const MetricSpec& spec, const LabSimulation& simulation)
      : joint_(metric_joint(spec, simulation)) {
    const double f = joint_.spec.distance.hertz;
    const double z = std::min(static_cast<double>(joint_.spec.distance.damping_ratio), 0.999);
    exact_frequency_ = f * std::sqrt(1.0 - z * z);
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    const BodyState& a = states[static_cast<std::size_t>(joint_.body_a)];
    const BodyState& b = states[static_cast<std::size_t>(joint_.body_b)];
    const vec2 span = world_point(b, joint_.local_anchor_b) - world_point(a, joint_.local_anchor_a);
    const vec2 relative = point_velocity(b, joint_.local_anchor_b) - point_velocity(a, joint_.local_anchor_a);
    const double length = std::hypot(span.x, span.y);
    turning_points_.add(time, length > 0.0 ? dot(span, relative) / length : 0.0);
  }
  double finite_error() const override {
    const double period = turning_points_.period();
    return period > 0.0 ? period_error_percent(1.0 / period, exact_frequency_) : 100.0;
  }

 private:
  LabJoint joint_;
  double exact_frequency_ = 1.0;
  SignChanges turning_points_;
};

/// True for the joints whose anchors JointDrift measures.
bool holds_anchors(const LabJoint& joint) {
  return joint.spec.type == JointType::Revolute || joint.spec.type == JointType::Weld ||
         (joint.spec.type == JointType::Distance && !joint.spec.distance.enable_spring);
}

class JointDriftTracker : public TrackerBase {
 public:
  JointDriftTracker(const MetricSpec& spec, const LabSimulation& simulation) : after_(spec.after) {
    const std::vector<LabJoint>& all = simulation.joints();
    if (spec.joints.empty()) {
      for (const LabJoint& joint : all) {
        if (holds_anchors(joint)) joints_.push_back(joint);
      }
    } else {
      for (std::size_t i = 0; i < spec.joints.size(); ++i) {
        MetricSpec one;
        one.joints = {spec.joints[i]};
        joints_.push_back(metric_joint(one, simulation));
      }
    }
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    if (time < after_ - 1e-9) return;
    for (const LabJoint& joint : joints_) {
      const vec2 span = world_point(states[static_cast<std::size_t>(joint.body_b)], joint.local_anchor_b) -
                        world_point(states[static_cast<std::size_t>(joint.body_a)], joint.local_anchor_a);
      double separation = std::hypot(span.x, span.y);
      if (joint.spec.type == JointType::Distance) separation = std::fabs(separation - joint.spec.distance.length);
      worst_ = std::max(worst_, separation);
    }
  }
  double finite_error() const override { return worst_; }

 private:
  std::vector<LabJoint> joints_;
  double after_ = 0.0;
  double worst_ = 0.0;
};

class RopeSlackTracker : public TrackerBase {
 public:
  RopeSlackTracker(const MetricSpec& spec, const LabSimulation& simulation,
                   const std::vector<BodyState>& start)
      : body_(spec.bodies.at(0)), joint_(metric_joint(spec, simulation)),
        start_(start.at(static_cast<std::size_t>(body_))), gravity_(simulation.gravity()) {
    const DistanceJointDef& rope = joint_.spec.distance;
    anchor_ = world_point(start.at(static_cast<std::size_t>(joint_.body_a)), joint_.local_anchor_a);
    max_length_ = rope.enable_limit ? rope.max_length : rope.length;
    min_length_ = rope.enable_limit ? rope.min_length : 0.0;
  }
  void observe_finite(double time, const std::vector<BodyState>& states) override {
    if (taut_) return;
    BodyState exact = start_;
    exact.position = {static_cast<float>(start_.position.x + start_.velocity.x * time + 0.5 * gravity_.x * time * time),
                      static_cast<float>(start_.position.y + start_.velocity.y * time + 0.5 * gravity_.y * time * time)};
    exact.angle = static_cast<float>(start_.angle + start_.angular_velocity * time);
    const vec2 rope = world_point(exact, joint_.local_anchor_b) - anchor_;
    const double length = std::hypot(rope.x, rope.y);
    if (length > max_length_ - 0.01 || length < min_length_ + 0.01) {
      taut_ = true;  // from here on the rope may act
      return;
    }
    const vec2 at = states[static_cast<std::size_t>(body_)].position;
    worst_ = std::max(worst_, static_cast<double>(std::hypot(at.x - exact.position.x, at.y - exact.position.y)));
  }
  double finite_error() const override { return worst_; }

 private:
  int body_;
  LabJoint joint_;
  BodyState start_;
  vec2 gravity_;
  vec2 anchor_{0.0f, 0.0f};
  double max_length_ = 0.0;
  double min_length_ = 0.0;
  bool taut_ = false;
  double worst_ = 0.0;
};

}  // namespace

double exact_pendulum_period(double length, double gravity, double amplitude) {
  return 4.0 * std::sqrt(length / gravity) * PendulumTracker::elliptic_k(std::sin(amplitude / 2.0));
}

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
    case MetricKind::PendulumPeriod:
      return std::make_unique<PendulumTracker>(spec, simulation, start);
    case MetricKind::SpringFrequency:
      return std::make_unique<SpringFrequencyTracker>(spec, simulation);
    case MetricKind::JointDrift:
      return std::make_unique<JointDriftTracker>(spec, simulation);
    case MetricKind::RopeSlack:
      return std::make_unique<RopeSlackTracker>(spec, simulation, start);
    case MetricKind::SurfaceRide:
      return std::make_unique<SurfaceRideTracker>(spec, simulation, start);
  }
  return nullptr;
}

}  // namespace impulse2d::lab

#pragma once
/// @file lab_metric.h
/// The error metric of a lab scenario: which exact answer the run is compared with, in which
/// unit, and the threshold under which the run passes.

#include <memory>
#include <string>
#include <vector>

#include "lab/lab_simulation.h"

namespace impulse2d::lab {

/// Which exact answer a scenario has.
enum class MetricKind {
  /// A body in free flight: p(t) = p0 + v0 t + g t^2 / 2. Error: largest distance from it, m.
  FreeFlight,
  /// A body on a static surface (its `surface`): a block holds iff |g_t| <= mu_s g_n, else
  /// slides with a = g_t -+ mu_d g_n (and stops after v0^2 / (2 a) when decelerating); a
  /// rolling disc (`rolls`) accelerates at 2/3 g_t iff mu_s >= |g_t| / (3 g_n), else slips.
  /// Error: largest distance along the surface from the exact position, m.
  SlopeMotion,
  /// A ball bouncing on the ground: apex k above the resting height is e^(2k) h0. Error: the
  /// largest apex error over `apex_count` apexes, m.
  BounceApexes,
  /// Two bodies colliding head-on: v1' = (m1 u1 + m2 u2 - m2 e (u1 - u2)) / (m1 + m2) and
  /// v2' = (m1 u1 + m2 u2 + m1 e (u1 - u2)) / (m1 + m2). Error: the larger velocity error at the
  /// end, as a fraction of the approach speed.
  Collision1d,
  /// Newton's cradle: the first ball hits a touching row; only the last ball leaves, with the
  /// first's velocity. Error: the largest velocity error at the end, fraction of that speed.
  Cradle,
  /// Mechanical energy of every dynamic body (kinetic, rotational, gravitational) is kept.
  /// Error: largest |E(t) - E(0)| / |E(0)|, percent.
  Energy,
  /// Nothing moves (resting stacks, pyramid): error is the largest distance of any dynamic
  /// body from where it started, m.
  Rest,
  /// A body flying at a wall (`surface`) must not pass it: error is how far the body's centre
  /// ends beyond the wall's centre, along the body's initial velocity (0 when it stays on its
  /// side), m.
  Tunnel,
  /// Overlapping bodies are separated without being thrown apart: error is the largest speed
  /// any dynamic body reaches during the run, m/s.
  PeakSpeed,
};

/// A scenario's metric as declared in its file.
struct MetricSpec {
  MetricKind kind = MetricKind::Rest;  ///< which exact answer
  std::vector<int> bodies;   ///< creation indices: the body (or bodies, in order) measured
  int surface = -1;          ///< SlopeMotion: creation index of the static surface
  bool rolls = false;        ///< SlopeMotion: the body is a disc rolling on the surface
  int apex_count = 3;        ///< BounceApexes: apexes compared
  float rest_height = 0.0f;  ///< BounceApexes: y of the ball's centre resting on the ground, m
  std::string unit;          ///< unit of the error ("m", "%", "1" for fractions)
  double threshold = 0.0;    ///< a run passes iff its error <= threshold (same unit)
  std::string meaning;       ///< one line: what the error measures
};

/// Follows a run and compares it with the exact answer.
class MetricTracker {
 public:
  virtual ~MetricTracker() = default;
  /// Called once per step after stepping, with the time since the start (s) and every body's
  /// state in creation order.
  virtual void observe(double time, const std::vector<BodyState>& states) = 0;
  /// The error so far, in the metric's unit (infinity for a run that went non-finite).
  virtual double error() const = 0;
};

/// A tracker for `spec` on `simulation`, taking the exact answer's initial conditions and the
/// contact coefficients of the simulation's own model from its state before the first step.
std::unique_ptr<MetricTracker> make_metric_tracker(const MetricSpec& spec,
                                                   const LabSimulation& simulation);

}  // namespace impulse2d::lab

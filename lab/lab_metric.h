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
  /// A pendulum: `body` swings on `joint` (a revolute hinge or a rigid distance joint whose
  /// body A is static) from rest at angle theta0 from straight below the pivot P (the joint's
  /// anchor on A). Energy conservation, (I_P / 2) (dtheta/dt)^2 = m g d (cos(theta) -
  /// cos(theta0)), with d the distance from P to the centre of mass and I_P = I + m d^2 the
  /// moment about P (I = 0 for a bob that cannot turn, which translates around the pivot),
  /// integrated over a quarter swing gives the period T = 4 sqrt(L/g) K(sin(theta0/2)),
  /// L = I_P / (m d) the equivalent length and K the complete elliptic integral of the first
  /// kind (computed by the arithmetic-geometric mean: K(k) = pi / (2 AGM(1, sqrt(1 - k^2)))).
  /// For small theta0 it is 2 pi sqrt(L/g) (1 + theta0^2/16 + ...). Measured: the times the
  /// bob crosses straight below the pivot (interpolated between steps); the period is twice
  /// the mean time between crossings. Error: |T_measured - T| / T, percent (100 when fewer
  /// than two crossings).
  PendulumPeriod,
  /// A mass on a spring: `joint` is a distance joint with a spring of f Hz and damping ratio z
  /// from a static body A to body B. The joint's spring is defined on the joint's reduced
  /// mass (B's mass when A is static), so the motion along the spring is x'' = -w^2 x - 2 z w x'
  /// with w = 2 pi f: it oscillates at f_d = f sqrt(1 - z^2) about its equilibrium (shifted by
  /// gravity along the spring, which does not change the frequency). Measured: the turning
  /// points (the spring's rate of lengthening changes sign, interpolated); the period is twice
  /// the mean time between them. Error: |f_measured - f_d| / f_d, percent (100 when fewer than
  /// two turning points).
  SpringFrequency,
  /// Joints must hold: a revolute or weld joint's two anchors coincide, a rigid distance
  /// joint's anchors stay `length` apart. Error: the largest anchor separation (|p_B - p_A|,
  /// or ||p_B - p_A| - length|) of the metric's `joints` (default: every revolute, weld and
  /// rigid distance joint) over the run (from `after` seconds on: "at rest" once the start's
  /// sag has settled), m.
  JointDrift,
  /// A slack rope: `body` hangs on `joint`, a distance joint with only a maximum length L
  /// (spring of 0 Hz, limit [min, L]); while the exact free-fall trajectory p(t) = p0 + v0 t +
  /// g t^2 / 2 stays within L - 1 cm of A's anchor (and beyond min + 1 cm) the rope must not
  /// act. Error: the largest distance from p(t) over that time, m.
  RopeSlack,
  /// A body riding a flat surface made of many pieces (a chain of one-sided segments: the
  /// ghost-collision test): `body` slides or rolls along `surface` (its angle is the
  /// surface's direction; for a chain, any link of it). On one flat surface nothing but the
  /// motion along it happens; `measure` says which part of that exact answer is scored:
  /// `normal_speed` the largest |v . n| (n the surface normal) over the run, m/s (exact 0: the
  /// body never leaves the surface nor is kicked at a seam); `angular_speed` the largest |w|,
  /// rad/s (exact 0 for a sliding block); `acceleration` the mean acceleration along the
  /// surface, (v_t(T) - v_t(0)) / T at the end of the run, against the exact one of
  /// `slope_motion`'s model (a block: g_t -+ mu_d g_n while sliding; a rolling disc (`rolls`):
  /// 2/3 g_t when mu_s >= |g_t| / (3 g_n), g_t -+ mu_d g_n when it slips), percent of the
  /// exact acceleration (semi-implicit Euler's velocities are exact for a constant one).
  /// The two speeds count from `after` seconds on (a body placed touching first sinks into its
  /// contact's slop: a settling, not a seam).
  SurfaceRide,
};

/// Which part of `SurfaceRide`'s exact answer a scenario scores.
enum class RideMeasure {
  NormalSpeed,   ///< largest |velocity across the surface|, m/s (exact 0)
  AngularSpeed,  ///< largest |angular velocity|, rad/s (exact 0 for a sliding block)
  Acceleration,  ///< mean acceleration along the surface against the exact one, percent
};

/// A scenario's metric as declared in its file.
struct MetricSpec {
  MetricKind kind = MetricKind::Rest;  ///< which exact answer
  std::vector<int> bodies;   ///< creation indices: the body (or bodies, in order) measured
  int surface = -1;          ///< SlopeMotion, SurfaceRide: creation index of the static surface
  bool rolls = false;        ///< SlopeMotion, SurfaceRide: the body is a disc rolling on it
  int apex_count = 3;        ///< BounceApexes: apexes compared
  float rest_height = 0.0f;  ///< BounceApexes: y of the ball's centre resting on the ground, m
  std::vector<int> joints;   ///< indices in the scene's `joints`: the joint(s) measured
  double after = 0.0;        ///< JointDrift, SurfaceRide: seconds from the start before errors count
  RideMeasure measure = RideMeasure::NormalSpeed;  ///< SurfaceRide: what is scored
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

/// The period (s) of a pendulum of equivalent length `length` (m) in gravity `gravity` (m/s^2)
/// swinging from rest at `amplitude` radians: 4 sqrt(L/g) K(sin(amplitude/2)).
double exact_pendulum_period(double length, double gravity, double amplitude);

/// A tracker for `spec` on `simulation`, taking the exact answer's initial conditions and the
/// contact coefficients of the simulation's own model from its state before the first step.
std::unique_ptr<MetricTracker> make_metric_tracker(const MetricSpec& spec,
                                                   const LabSimulation& simulation);

}  // namespace impulse2d::lab

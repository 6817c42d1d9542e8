// The stability map's boundaries pinned from both sides, so a regression in either direction
// fails: each measured threshold (impulse2d lab; README "Where methods fail") is checked to
// pass a margin below it and to fail a margin above it. Where the boundary has a closed form
// (tunnelling) the test predicts it instead of pinning a number.
#include <gtest/gtest.h>

#include <cmath>

#include "lab/stability_map.h"
#include "lab/stressors.h"

namespace impulse2d::lab {
namespace {

const Stressor& stressor(const std::string& name) {
  static const std::vector<Stressor> all = stressors(false);
  for (const Stressor& each : all) {
    if (each.name == name) return each;
  }
  throw std::runtime_error("no stressor " + name);
}

bool passes(const std::string& name, double value, const LabMethod& method) {
  return stress_passes(stressor(name), value, method, nullptr);
}

/// The default (the soft step, 4 sub-steps of 1 pass) with neither CCD nor speculative
/// contacts: collision only between shapes that overlap.
LabMethod discrete() {
  LabMethod method;
  method.continuous = false;
  method.speculative_margin = 0.0f;
  return method;
}

/// Speculative contacts (the default margin) without CCD.
LabMethod speculative_only() {
  LabMethod method;
  method.continuous = false;
  return method;
}

/// The tutorial's solver at its 10 iterations with linear projection, one step a frame.
LabMethod per_iteration() {
  LabMethod method = method_for(SolverMethod::PerIteration);
  method.velocity_iterations = 10;
  method.position_correction = PositionCorrection::LinearProjection;
  return method;
}

/// Accumulated impulses at their own budget (settings_for: one step of 16 iterations).
LabMethod accumulated() { return method_for(SolverMethod::Accumulated); }

/// Discrete collision of the bullet stressor's ball (radius 0.1 m, from x = -3 m at v m/s, one
/// step of 1/60 s) with the wall (half thickness 0.05 m, centred at x = 0): contacts are found
/// from the positions a step ends at, x_k = -3 + k v dt. The first such position that overlaps
/// the wall (x_k > -0.15) decides: a centre short of the wall's mid-plane is pushed back; a
/// centre past it is pushed through, as is a ball that never overlaps. Returns nothing when the
/// deciding position is within 1 mm of either edge (float rounding could go either way).
std::optional<bool> predicted_tunnel(double speed) {
  const double dt = 1.0 / 60.0, reach = 0.15;
  for (int k = 1; k < 100000; ++k) {
    const double x = -3.0 + k * speed * dt;
    if (x > -reach - 1e-3 && x < -reach + 1e-3) return std::nullopt;
    if (x <= -reach) continue;
    if (std::fabs(x) < 1e-3) return std::nullopt;
    return x >= 0.0;
  }
  return std::nullopt;
}

// Discrete collision tunnels exactly when the step carries the centre past the wall's
// mid-plane (first tunnelling speed ~20 m/s here: 0.15 m reach at 1/60 s is 9 m/s, the start
// phase decides the rest); speculative contacts alone never do, up to 2 km/s (their reach grows
// with the body's speed). Contacts are found once a step in every solver, the soft step's
// sub-steps included, so the prediction holds for the default as for one step a frame.
TEST(LabBoundaries, DiscreteCollisionTunnelsOnceTheStepPassesTheMidPlane) {
  for (const LabMethod& base : {discrete(), [] {
         LabMethod method = accumulated();
         method.continuous = false;
         method.speculative_margin = 0.0f;
         return method;
       }()}) {
    int checked = 0, tunnelled = 0;
    for (double speed = 4.0; speed <= 60.0; speed += 0.75) {
      const std::optional<bool> tunnel = predicted_tunnel(speed);
      if (!tunnel) continue;
      ++checked;
      tunnelled += *tunnel ? 1 : 0;
      EXPECT_EQ(passes("bullet_speed", speed, base), !*tunnel)
          << method_label(base) << ", " << speed << " m/s";
    }
    EXPECT_GT(checked, 60);
    EXPECT_GT(tunnelled, 20);  // both sides of the boundary were exercised
  }
  for (const double speed : {20.0, 100.0, 500.0, 2048.0}) {
    EXPECT_TRUE(passes("bullet_speed", speed, speculative_only())) << speed << " m/s speculative";
  }
}

// CCD alone (no speculative contacts) never tunnels, up to 2 km/s, with every solver at its own
// budget. KNOWN ENGINE DEFECT (the soft step; reported, not worked around): the sweep moves a
// bullet back to the first overlapping pose and keeps its speed; the next step's contact is
// then an overlapping one, which the soft step solves softly (mass scale < 1 at 60 Hz and
// damping ratio 10), so about 2.4 % of the approach speed survives the first sub-step; from
// ~1.5 km/s at 4 sub-steps (~1 km/s at one) that carries the centre past the wall's mid-plane
// and the next collide pushes the ball out the far side. Accumulated impulses stop it (hard
// contact).
TEST(LabBoundaries, CcdAloneNeverTunnelsWithAnySolver) {
  for (const SolverMethod solver : solver_methods()) {
    LabMethod ccd_only = method_for(solver);
    ccd_only.speculative_margin = 0.0f;
    for (const double speed : {20.0, 100.0, 500.0, 2048.0}) {
      EXPECT_TRUE(passes("bullet_speed", speed, ccd_only))
          << speed << " m/s with CCD, " << method_label(ccd_only);
    }
  }
}

/// Accumulated impulses at 4 substeps of 2 iterations.
LabMethod substepped() {
  LabMethod method = accumulated();
  method.substeps = 4;
  method.velocity_iterations = 2;
  return method;
}

/// The default: the soft step, 4 sub-steps of 1 pass.
LabMethod soft_step() { return LabMethod{}; }

LabMethod accumulated_no_shock() {
  LabMethod method = accumulated();
  method.shock_propagation = false;
  return method;
}

LabMethod soft_step_no_shock() {
  LabMethod method;
  method.shock_propagation = false;
  return method;
}

LabMethod accumulated_no_warm_start() {
  LabMethod method = accumulated();
  method.warm_starting = false;
  return method;
}

LabMethod soft_step_no_warm_start() {
  LabMethod method;
  method.warm_starting = false;
  return method;
}

/// A measured boundary: `method` passes `stressor` at `holds` and fails at `breaks`. The values
/// sit a margin outside the thresholds measured by `impulse2d lab` (in the comments); when a
/// solver change moves a boundary on purpose, re-measure (`impulse2d lab --no-sweep`, 10 s) and
/// update this table.
struct Boundary {
  const char* name;
  LabMethod (*method)();
  const char* stressor;
  double holds;
  double breaks;
};

const Boundary boundaries[] = {
    // Stacks standing 30 s, with contact recycling (re-measured after the soft step became the
    // default, issue 26): accumulated impulses (16 iterations) and 4 substeps x 2 iterations
    // hold 40 boxes (the whole ladder; 38 and 39 before recycling); without warm starting 4
    // and not 5, as is the soft step without it; the default soft step 30 and not 31 (as
    // before issue 26; 11 and 12 before recycling).
    {"accumulated", accumulated, "stack_height", 40, -1},
    {"accumulated, no warm start", accumulated_no_warm_start, "stack_height", 3, 6},
    {"4 substeps x 2 iterations", substepped, "stack_height", 40, -1},
    {"soft step", soft_step, "stack_height", 25, 35},
    {"soft step, no warm start", soft_step_no_warm_start, "stack_height", 3, 6},
    // Heavy on light: with shock propagation both solvers pass the whole ladder (to 10^4x; the
    // soft step has had the pass since issue 26: 47x before, as it still passes 47.1x and fails
    // 50.8x without it); accumulated impulses without it pass 262x and fail 280x (unchanged);
    // without warm starting 7.98x passes, 8.60x fails (7.4x and 8.0x before issue 26).
    {"accumulated", accumulated, "mass_ratio", 10000, -1},
    {"soft step", soft_step, "mass_ratio", 10000, -1},
    {"accumulated without shock propagation", accumulated_no_shock, "mass_ratio", 100, 300},
    {"soft step without shock propagation", soft_step_no_shock, "mass_ratio", 30, 100},
    {"accumulated, no warm start", accumulated_no_warm_start, "mass_ratio", 3, 10},
    // A 10-stack under a coarser step, with contact recycling: 16 iterations stand at 77.6 ms,
    // fall at 79.6 ms (unchanged by issue 26; 41.9 and 43.0 before recycling); 4 substeps x 2
    // iterations stand at 100 ms, the whole ladder (50 and 50.9 before recycling); the soft
    // step stands at 60.9 ms and falls at 62.0 ms (61 ms before issue 26).
    {"accumulated", accumulated, "time_step", 1000.0 / 15, 90},
    {"4 substeps x 2 iterations", substepped, "time_step", 100, -1},
    {"soft step", soft_step, "time_step", 50, 1000.0 / 15},
    // Static/dynamic friction: accumulated impulses hold at atan(mu_s) - 0.1 degrees and slide
    // as predicted at + 0.1 (the whole ladder; unchanged); the soft step is right to 0.420
    // degrees and wrong at 0.403 (0.188 and 0.177 before issue 26: its friction is now one
    // constraint at the middle of the points).
    {"accumulated", accumulated, "friction_angle", 0.1, -1},
    {"soft step", soft_step, "friction_angle", 0.5, 0.35},
    // Elastic pile under gravity, energy within 5 % for 10 s: since issue 26 (bounces of one
    // step raised together) both solvers keep the whole ladder, 32 discs (before: the soft step
    // 14 and not 15, accumulated impulses 2 and not 3); explicit Euler keeps 1 and not 2.
    {"soft step", soft_step, "elastic_pile", 32, -1},
    {"accumulated", accumulated, "elastic_pile", 32, -1},
};

TEST(LabBoundaries, MeasuredThresholdsHoldFromBothSides) {
  for (const Boundary& boundary : boundaries) {
    const LabMethod method = boundary.method();
    EXPECT_TRUE(passes(boundary.stressor, boundary.holds, method))
        << boundary.name << " should pass " << boundary.stressor << " at " << boundary.holds;
    if (boundary.breaks >= 0) {
      EXPECT_FALSE(passes(boundary.stressor, boundary.breaks, method))
          << boundary.name << " should fail " << boundary.stressor << " at " << boundary.breaks;
    }
  }
}

// The per-iteration solver fails a stack height that the accumulated solver (and the default,
// the soft step) holds.
TEST(LabBoundaries, PerIterationFailsAStackThatAccumulatedHolds) {
  EXPECT_FALSE(passes("stack_height", 2, per_iteration()));
  EXPECT_TRUE(passes("stack_height", 2, accumulated()));
  EXPECT_TRUE(passes("stack_height", 2, LabMethod{}));
}

// Built overlapping by up to 0.45 m (of 1 m boxes), every impulse2d method separates the boxes
// without throwing them apart faster than 1 m/s.
TEST(LabBoundaries, OverlapIsResolvedWithoutExplosionByEveryMethod) {
  for (const LabMethod& method : {LabMethod{}, accumulated(), per_iteration(), substepped()}) {
    EXPECT_TRUE(passes("initial_overlap", 0.45, method)) << method_label(method);
  }
}

}  // namespace
}  // namespace impulse2d::lab

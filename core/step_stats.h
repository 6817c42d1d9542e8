#pragma once
/// @file step_stats.h
/// What the last step did and how long each stage took.

#include <cstdint>

namespace impulse2d {

/// Counts and wall-clock times of the last `World::step`. Times vary from run to run; they are
/// for profiling and benchmarks, never part of the state hash.
struct StepStats {
  int body_count = 0;          ///< bodies in the world
  int awake_body_count = 0;    ///< non-static bodies not sleeping
  int pairs_tested = 0;        ///< candidate pairs given to the narrow phase
  int contact_count = 0;       ///< touching pairs after the narrow phase
  int contact_point_count = 0; ///< manifold points after the narrow phase
  int sleeping_contact_count = 0;  ///< touching pairs set aside while none of their bodies moves
  int bullets_moved_back = 0;  ///< bullets stopped at their time of impact by the sweep
  double broad_phase_ms = 0.0;   ///< time finding candidate pairs
  /// Time in collide functions and contact matching, and in the solver's work on each contact
  /// as the narrow phase finishes it (the soft step prepares and colours there).
  double narrow_phase_ms = 0.0;
  double solver_ms = 0.0;        ///< time in velocity iterations
  double integrate_ms = 0.0;     ///< time integrating velocities and positions
  double position_ms = 0.0;      ///< time in position correction
  double total_ms = 0.0;         ///< whole step
};

}  // namespace impulse2d

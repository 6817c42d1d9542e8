#pragma once
/// @file compare_run.h
/// Running one scene in every engine in the same process, interleaved: `block` steps of the
/// first engine, `block` of the second, ..., then again, so that a busy machine slows them all
/// alike. Each step is timed alone (CPU time of the thread); the recycling of rain and the
/// stability samples are outside the timed steps.

#include <string>
#include <vector>

#include "bench/compare/compare_scene.h"
#include "bench/compare/stability.h"
#include "lab/lab_method.h"

namespace impulse2d::compare {

/// One engine of the comparison, with its settings.
struct Contender {
  std::string label;      ///< short name for tables and the chart, e.g. "impulse2d accumulated 16i"
  lab::LabMethod method;  ///< engine and settings (a peer's iteration counts)
};

/// impulse2d's default settings, impulse2d's soft step (4 substeps x 1 iteration), Box2D 2.4.1
/// (8 velocity / 3 position iterations) and Chipmunk 7 (10 iterations), at 1/60 s, sleeping
/// off; a peer only when it was compiled in (`notes` gets the reason when not, and notes such
/// as Chipmunk's debug build).
std::vector<Contender> contenders(std::vector<std::string>& notes);

/// The memory one engine's world holds once built and stepped, bytes (negative: not measured).
struct MemoryUse {
  /// Growth of the bytes malloc has handed out and not taken back (glibc `mallinfo2`: in use
  /// in the arenas plus mmapped blocks): the world, its buffers' whole capacity, the adapter.
  double heap_bytes = -1.0;
  /// Growth of the process's resident set (`/proc/self/statm`, after `malloc_trim(0)` before
  /// and after): the pages actually touched.
  double resident_bytes = -1.0;
};

/// impulse2d's world settings for `method` on `scene`, exactly as `run_interleaved` steps it:
/// gravity -10 m/s^2, 1/60 s, sleeping off, one thread, the method's solver settings (the
/// default `LabMethod{}` is the default soft step, `WorldSettings::solver_lanes` 0).
WorldSettings impulse2d_settings(const CompareScene& scene, const lab::LabMethod& method);

/// One engine's result on one scene.
struct Outcome {
  bool ran = true;           ///< false when the engine was left out of the scene (`--peers-max`)
  double ms_per_step = 0.0;  ///< median CPU time of a step, milliseconds
  Stability stability;       ///< what the run left standing
  MemoryUse memory;          ///< measured for the scaling series only (`measure_memory`)
};

/// Runs `scene` for `steps` steps in every contender whose `included` entry is true,
/// interleaved in blocks of `block` steps; samples the deepest overlap about five times in the
/// run and at its end. One outcome per contender, in order (`ran` false for those left out).
std::vector<Outcome> run_interleaved(const CompareScene& scene,
                                     const std::vector<Contender>& contenders,
                                     const std::vector<bool>& included, int steps, int block);

/// Builds `scene` in `contender`'s engine alone, steps it `steps` times, and returns how much
/// the heap in use and the resident set grew from before it was built (then frees it). The
/// scene's own body list exists before and is not counted.
MemoryUse measure_memory(const CompareScene& scene, const Contender& contender, int steps);

}  // namespace impulse2d::compare

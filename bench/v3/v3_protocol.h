#pragma once
/// @file v3_protocol.h
/// What bench_v3 and its Box2D v3 runners share: the scenes by name (bench_compare's own), the
/// timing loop both engines are measured by, and the one machine-readable line a runner prints.

#include <functional>
#include <string>
#include <vector>

#include "bench/compare/compare_scene.h"
#include "bench/compare/stability.h"

namespace impulse2d::bench_v3 {

/// The scenes bench_v3 runs, in its order: "large_pyramid", "many_pyramids", "ball_pit".
const std::vector<std::string>& scene_names();

/// The steps of a full run of a size of the scaling series (bench_compare's own).
constexpr int scaling_steps = 100;

/// The name bench_v3 and its runners give the scaling scene of `bodies` bodies:
/// "scaling_<bodies>", as bench_compare names it.
std::string scaling_name(int bodies);

/// True when `name` is one of `scene_names` or names a size of `compare::scaling_sizes`.
bool known_scene(const std::string& name);

/// bench_compare's scene `name` (`known_scene`) as bench_compare.cpp builds it, with its
/// full step count: Box2D v3's large_pyramid (100 rows, 500 steps), many_pyramids (400
/// pyramids of 10 rows, 20 to a ground, 200 steps), the ball pit (5000 balls in rows of 100,
/// 300 steps), a size of the scaling series ("scaling_990" .. "scaling_100100",
/// `compare::scaling_scene`, `scaling_steps`). Throws `std::invalid_argument` for another name.
compare::CompareScene scene_by_name(const std::string& name);

/// CPU time of the calling thread, milliseconds (`CLOCK_THREAD_CPUTIME_ID`).
double thread_cpu_ms();

/// Bytes malloc has handed out and not taken back (glibc `mallinfo2`: in use in the arenas
/// plus mmapped blocks), as bench_compare measures heap per body.
double heap_in_use();

/// Calls `step` `warmup` times untimed, then `steps` times each timed alone by
/// `thread_cpu_ms`; returns the `steps` times, milliseconds, in order.
std::vector<double> timed_steps(const std::function<void()>& step, int warmup, int steps);

/// The median of `values` (the mean of the two middle ones for an even count); 0 when empty.
double median(std::vector<double> values);

/// A value measured once per round, summarised over the rounds.
struct Spread {
  double median = 0.0;  ///< median of the rounds (`median`)
  double min = 0.0;     ///< smallest
  double max = 0.0;     ///< largest
};

/// The median and range of `values`; throws `std::invalid_argument` when `values` is empty or
/// one is not finite and positive.
Spread spread_of(const std::vector<double>& values);

/// One run of one scene in one engine build: what a runner reports and bench_v3 measures of
/// impulse2d alike.
struct RunResult {
  std::string scene;       ///< scene name, e.g. "large_pyramid"
  std::string width;       ///< the build's vector width: "sse2" or "avx2" (runner line only)
  std::string commit;      ///< Box2D v3 commit, 40 hex digits (runner line only)
  int steps = 0;           ///< measured steps
  int warmup = 0;          ///< untimed steps before them
  double median_ms = 0.0;  ///< median CPU time of a measured step, milliseconds
  double min_ms = 0.0;     ///< fastest measured step, milliseconds
  /// What the run left, judged as bench_compare judges it (`compare::judge_final_states`, and
  /// `depth` = `compare::deepest_overlap` of the final states only).
  compare::Stability stability;
  /// Growth of `heap_in_use` from before the world was built to after the last step, bytes:
  /// the world with its buffers' whole capacity and the list of body handles.
  double heap_bytes = 0.0;
};

/// Judges the final `states` of a run of `scene` into `result.stability`: sag, side, moved,
/// out, non_finite and the deepest overlap at the end.
void judge(const compare::CompareScene& scene, const std::vector<lab::BodyState>& states,
           RunResult& result);

/// The runner's line (no newline): `v3_runner` then, separated by single spaces and in this
/// order, scene= width= commit= steps= warmup= median_ms= min_ms= sag= side= moved= out=
/// non_finite= depth= heap_bytes=; times and lengths with 6 decimals, bytes whole.
std::string format_runner_line(const RunResult& result);

/// Parses a line made by `format_runner_line` (a trailing newline allowed), strictly: every
/// key present, in order, once; numbers whole (no trailing characters), finite, not negative;
/// the scene `known_scene`; the commit 40 lower-case hex digits; width sse2 or avx2. Throws `std::runtime_error` whose
/// message names `runner` and says what is wrong.
RunResult parse_runner_line(const std::string& line, const std::string& runner);

/// A whole number in `minimum`..100000000 from `text` (all of it, decimal digits only), or -1.
int parse_count(const std::string& text, int minimum = 1);

}  // namespace impulse2d::bench_v3

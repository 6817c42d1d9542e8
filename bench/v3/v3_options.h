#pragma once
/// @file v3_options.h
/// bench_v3's command line.

#include <stdexcept>
#include <string>
#include <vector>

#include "bench/compare/compare_scene.h"

namespace impulse2d::bench_v3 {

/// What bench_v3 was asked to do.
struct Options {
  int rounds = 5;    ///< alternated rounds (pairs per scene and width)
  int steps = -1;    ///< measured steps per run; -1: each scene's own (a fifth with `quick`)
  int warmup = 1;    ///< untimed steps before them (Box2D v3's benchmark leaves its first out)
  bool quick = false;               ///< a fifth of each scene's steps
  std::vector<std::string> scenes;  ///< in bench_v3's order, each once; all when none named; none with `scale`
  bool scale = false;  ///< the scaling series instead of the scenes
  int scale_max = -1;  ///< with `scale`: its largest size, bodies; -1: all of it
  std::string out;                  ///< directory for table.md; empty: print only
  bool help = false;                ///< print the usage and exit 0
};

/// A bad command line; the message says what is wrong.
class UsageError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The usage text (no trailing newline).
const char* usage_text();

/// Parses bench_v3's arguments (without the program name): --rounds R, --steps N, --warmup W,
/// --quick, --scene NAME (repeatable, or a comma list), --scale, --scale-max BODIES, --out DIR,
/// --help. Throws `UsageError` on an unknown argument, a missing or bad value, an unknown
/// scene, --scene with --scale, --scale-max without --scale, or a --scale-max below the
/// smallest size of the series (990 bodies).
Options parse_options(const std::vector<std::string>& arguments);

/// The steps each run of `scene` measures under `options`: `steps` when given, else the
/// scene's own `full_steps`, divided by 5 with `quick` (as bench_compare --quick), at least 1.
int measured_steps(const Options& options, int full_steps);

/// The sizes of the scaling series `options` asks for: `compare::scaling_sizes` up to
/// `scale_max` bodies (all when it is -1), fewest bodies first.
std::vector<compare::ScalingSize> scale_sizes(const Options& options);

}  // namespace impulse2d::bench_v3

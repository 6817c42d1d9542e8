#pragma once
/// @file v3_options.h
/// bench_v3's command line.

#include <stdexcept>
#include <string>
#include <vector>

namespace impulse2d::bench_v3 {

/// What bench_v3 was asked to do.
struct Options {
  int rounds = 5;    ///< alternated rounds (pairs per scene and width)
  int steps = -1;    ///< measured steps per run; -1: each scene's own (a fifth with `quick`)
  int warmup = 1;    ///< untimed steps before them (Box2D v3's benchmark leaves its first out)
  bool quick = false;               ///< a fifth of each scene's steps
  std::vector<std::string> scenes;  ///< in bench_v3's order, each once; all when none named
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
/// --quick, --scene NAME (repeatable, or a comma list), --out DIR, --help. Throws `UsageError`
/// on an unknown argument, a missing or bad value, or an unknown scene.
Options parse_options(const std::vector<std::string>& arguments);

/// The steps each run of `scene` measures under `options`: `steps` when given, else the
/// scene's own `full_steps`, divided by 5 with `quick` (as bench_compare --quick), at least 1.
int measured_steps(const Options& options, int full_steps);

}  // namespace impulse2d::bench_v3

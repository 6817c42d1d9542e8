#pragma once
/// @file lab_command.h
/// `impulse2d lab`, `impulse2d lab merge` and `impulse2d tune` as plain functions of their
/// arguments (the command line's parsing is in app/command_lab.cpp and app/command_tune.cpp).
/// Progress goes to stderr, the report to `out`; bad input throws `demos::UsageError` (exit status 2).

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace impulse2d::lab {

/// `impulse2d lab`.
struct LabArguments {
  bool quick = false;                   ///< smaller method space, 2 repeats, short stability map
  std::string scenarios;                ///< scenario directory (default: the source tree's)
  std::vector<std::string> only;        ///< run only these scenarios (names)
  std::string out = "out/lab";          ///< output directory
  int repeats = 0;                      ///< timed repeats (0: 3, or 2 with --quick)
  std::string shard = "1/1";            ///< K/N: run every N-th configuration starting at K
  bool peers = true;                    ///< run Box2D and Chipmunk when compiled in
  bool charts = true;                   ///< draw the PNG charts (needs gnuplot)
  bool stability = true;                ///< also run the stability map
  bool sweep = true;                    ///< run the method sweep (off: the stability map only)
  bool quiet = false;                   ///< no progress bars on stderr
};

/// `impulse2d lab merge`.
struct MergeArguments {
  std::vector<std::string> inputs;  ///< shard CSVs
  std::string out = "out/lab";      ///< output directory (lab.csv and charts)
  bool charts = true;               ///< draw the charts of the merged result
};

/// `impulse2d tune`.
struct TuneArguments {
  std::string scene;                ///< built-in scene name or .json scene file
  std::vector<std::string> params;  ///< scene parameters key=value
  double max_error = -1.0;          ///< metres (required, > 0)
  std::string metric = "final";     ///< final | trajectory
  std::optional<double> duration;   ///< seconds simulated (default: the scene's run)
  bool quick = false;               ///< a smaller search space
  int repeats = 3;                  ///< timed repeats per candidate
  std::string out;                  ///< also write the answer as a JSON file here ("" = no)
};

/// Runs the sweep (and the stability map), writes CSVs and charts; prints where they went.
void run_lab(const LabArguments& arguments, std::ostream& out);
/// Joins shard CSVs into one, recomputes the fronts, redraws the charts.
void merge_lab(const MergeArguments& arguments, std::ostream& out);
/// Finds the cheapest configuration within the error bound and prints it as JSON settings.
void run_tune(const TuneArguments& arguments, std::ostream& out);

/// Parses "K/N" (1 <= K <= N). Throws `demos::UsageError` naming --shard.
std::pair<int, int> parse_shard(const std::string& text);

}  // namespace impulse2d::lab

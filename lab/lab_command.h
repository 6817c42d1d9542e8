#pragma once
/// @file lab_command.h
/// `impulse2d lab`, `impulse2d lab merge` and `impulse2d tune` as plain functions of their
/// arguments (the command line's parsing is in app/command_lab.cpp and app/command_tune.cpp).
/// Every check (numbers, input files, output paths, the work budget) runs before any work; the
/// `plan_*` functions run the same checks and print what the run would do (--dry-run).
/// Progress goes to stderr, the report to `out`; bad input throws `demos::UsageError` (exit
/// status 2), a signal `demos::Interrupted`, a failed write `std::runtime_error`; the output is
/// then as it was before the run.

#include <ostream>
#include <string>
#include <vector>

namespace impulse2d::lab {

/// `impulse2d lab`.
struct LabArguments {
  bool quick = false;                   ///< smaller method space, 2 repeats, short stability map
  std::string scenarios;                ///< scenario directory (default: the installed ones)
  std::vector<std::string> only;        ///< run only these scenarios (names)
  std::string out = "out/lab";          ///< output directory
  std::string repeats;                  ///< timed repeats, 1..100 as digits ("": 3, or 2 with --quick)
  std::string shard = "1/1";            ///< K/N: run every N-th configuration starting at K
  bool peers = true;                    ///< run Box2D and Chipmunk when compiled in
  bool charts = true;                   ///< draw the PNG charts (needs gnuplot)
  bool stability = true;                ///< also run the stability map
  bool sweep = true;                    ///< run the method sweep (off: the stability map only)
  bool clean = false;                   ///< replace another run's results found in `out`
  bool force = false;                   ///< run even above the work bound (`max_lab_runs`)
  bool quiet = false;                   ///< no progress bars on stderr
  /// Threads sharing each step of the sweep's scenarios (`WorldSettings::worker_count`), 1..64;
  /// the results are the same for any count, the timings are not.
  int workers = 1;
};

/// `impulse2d lab merge`.
struct MergeArguments {
  std::vector<std::string> inputs;  ///< shard CSVs
  std::string out = "out/lab";      ///< output directory (lab.csv and charts)
  bool charts = true;               ///< draw the charts of the merged result
  bool clean = false;               ///< replace another run's results found in `out`
};

/// `impulse2d tune`.
struct TuneArguments {
  std::string scene;                ///< built-in scene name or .json scene file
  std::vector<std::string> params;  ///< scene parameters key=value
  std::string max_error;            ///< metres, in (0, 1000] (required)
  std::string metric = "final";     ///< final | trajectory
  std::string duration;             ///< seconds simulated, in (0, 3600] ("": the scene's run)
  bool quick = false;               ///< a smaller search space
  std::string repeats = "3";        ///< timed repeats per candidate, 1..100
  std::string out;                  ///< also write the answer as a JSON file here ("" = no)
  bool force = false;               ///< run even above the work bound (`max_tune_steps`)
  bool quiet = false;               ///< no progress bar on stderr
};

/// Runs the sweep (and the stability map), writes CSVs and charts as one unit; prints where
/// they went.
void run_lab(const LabArguments& arguments, std::ostream& out);
/// `lab --dry-run`: every check of `run_lab`, then the plan (runs, estimate, files) to `out`.
void plan_lab(const LabArguments& arguments, std::ostream& out);

/// Joins shard CSVs into one, recomputes the fronts, redraws the charts (as one unit).
void merge_lab(const MergeArguments& arguments, std::ostream& out);
/// `lab merge --dry-run`: every check of `merge_lab`, then the plan to `out`.
void plan_merge(const MergeArguments& arguments, std::ostream& out);

/// Finds the cheapest configuration within the error bound and prints it as JSON settings.
void run_tune(const TuneArguments& arguments, std::ostream& out);
/// `tune --dry-run`: every check of `run_tune`, then the plan to `out`.
void plan_tune(const TuneArguments& arguments, std::ostream& out);

}  // namespace impulse2d::lab

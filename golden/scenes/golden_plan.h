#pragma once
/// @file golden_plan.h
/// What `impulse2d golden check|update|frame` will do, found by the checks a run makes before
/// any work (arguments, every scene file and golden block, CI, every output path): the run
/// starts from it, and `--dry-run` prints it and stops.

#include <iosfwd>
#include <vector>

#include "golden/scenes/golden_block.h"
#include "golden/scenes/golden_command.h"

namespace impulse2d::golden {

/// The validated input of a run.
struct GoldenPlan {
  std::vector<SceneGoldens> scenes;  ///< every scene file's goldens, in the order given
};

/// The file that marks a folder as a golden report, so a later run may replace it.
inline constexpr const char* kReportMarker = ".impulse2d-golden-report";

/// Runs every check a run makes before any work and returns what it validated. Throws
/// `demos::UsageError` naming the file, field or option: no scene file, `--repeat` not 1
/// or 2, `update` under CI, an invalid scene file or golden block, a `--report` that is not
/// a folder or holds something else than an earlier report, a `--junit` or `--out` that
/// cannot be written (a folder, a missing or read-only folder), an unknown frame name.
GoldenPlan plan_golden_command(const GoldenCommandArguments& arguments);

/// Prints the plan: the scene files, the goldens (count, files, present or missing), the
/// files a run would write, and an interrupted update it would finish or undo first.
void print_golden_plan(const GoldenCommandArguments& arguments, const GoldenPlan& plan,
                       std::ostream& out);

}  // namespace impulse2d::golden

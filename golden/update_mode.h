#pragma once
/// @file update_mode.h
/// When the golden suite may write goldens: GOLDEN_UPDATE=none|missing|changed|all, forced
/// to none under CI so a CI run can never bless its own output.

#include "golden/failure.h"

#include <string>

namespace impulse2d::golden {

/// Which goldens a run writes.
enum class UpdateMode {
  None,     ///< never write goldens; a missing golden fails (the default)
  Missing,  ///< write goldens (and renderer baselines) that do not exist yet; compare the rest
  Changed,  ///< write missing goldens and those that fail their comparison
  All,      ///< rewrite every golden
};

/// The mode a run uses and, when the request was overridden, why.
struct UpdateModeChoice {
  UpdateMode mode = UpdateMode::None;  ///< the mode in force
  std::string note;  ///< e.g. "GOLDEN_UPDATE=all ignored: CI=true forces none"; else empty
};

/// True when the CI variable's value says "this is CI": any non-empty value except
/// "false", "0", "no" and "off" (any case). CI services set "true", "1" or "yes".
bool is_ci(const char* ci);

/// Resolves the mode from the two variables' values (null when unset). Unset or empty
/// GOLDEN_UPDATE means none. CI (`is_ci`) forces none, with a note when another mode was
/// asked for. Throws `GoldenError` for a value that is not a mode, even
/// under CI.
UpdateModeChoice resolve_update_mode(const char* golden_update, const char* ci);

/// `resolve_update_mode` from the process environment; prints the note, if any, to stderr.
UpdateModeChoice update_mode_from_environment();

/// "none", "missing", "changed" or "all".
std::string update_mode_name(UpdateMode mode);

/// True when a run in `mode` writes the golden after a check of class `outcome`. A
/// nondeterministic frame is never written, in any mode.
bool should_write_golden(UpdateMode mode, FailureClass outcome);

}  // namespace impulse2d::golden

#pragma once
/// @file golden_command.h
/// `impulse2d golden check|update|frame`: the golden harness for any JSON scene file with a
/// `golden` block (golden_block.h), as a user's CI runs it.
///
/// - `check FILE...`  checks every golden frame of every file; exit 0 all match, 1 any
///   failure (classified as the suite classifies), 2 bad input. `--repeat 2` also renders
///   each frame in a second process (nondeterminism across processes).
/// - `update FILE...` writes missing and failing goldens (`--all`: every one), each only after
///   a second process rendered the same frame, with its noise envelope; refused under CI.
/// - `frame FILE NAME --out PNG` renders one golden frame (the second process of the other
///   two) into PNG and its state hash into PNG.hash; with `start_run`, from a saved state.
/// Failures leave their artifacts and index.html in `--report DIR` (default
/// golden_artifacts), which holds only this run's results; `--junit FILE` writes JUnit XML.
/// Frames whose renderer has no baseline are checked by their physics only, and the run
/// ends with one line per such renderer saying how many frames went unchecked for pixels;
/// `--require-pixels` (or IMPULSE2D_REQUIRE_PIXELS=1) makes each of them a failure.
/// An update is a transaction (staged_update.h): an interrupted or failed one leaves the
/// whole old set of goldens, a finished one the whole new set.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace impulse2d::demos {
class SceneRun;
}

namespace impulse2d::golden {

/// The command's arguments, as the CLI parses them.
struct GoldenCommandArguments {
  std::string action;               ///< "check", "update" or "frame"
  std::vector<std::string> files;   ///< scene files
  std::string report_dir = "golden_artifacts";  ///< artifacts and index.html of this run
  std::string junit;                ///< JUnit XML file; empty: none
  int repeat = 1;                   ///< check: processes per frame (1 or 2)
  bool all = false;                 ///< update: rewrite every golden, not only failing ones
  /// check: a frame drawn by a renderer without a baseline fails instead of being checked by
  /// its physics only (also set by IMPULSE2D_REQUIRE_PIXELS=1).
  bool require_pixels = false;
  std::string frame;                ///< frame: the golden frame's name
  std::string out;                  ///< frame: the PNG to write
  /// frame: continues the run before its first step to at most the golden's step (the CLI's
  /// `--load-state`: a state saved by `trace --save-state`), `RunStart` of golden_run.h; the
  /// frame's step stays the golden's own. Empty: the run starts from the scene.
  std::function<void(demos::SceneRun& run, std::int64_t frame_step)> start_run;
  std::string executable;           ///< this program, for the second process
  /// Threads sharing each step (`WorldSettings::worker_count`), 1..64: the frames and states
  /// are the same for any count.
  int workers = 1;
};

/// Exit status: every golden matched (or was written).
inline constexpr int kGoldenPassed = 0;
/// Exit status: at least one golden failed, or the run itself failed (a write, the
/// renderer, the second process).
inline constexpr int kGoldenFailed = 1;
/// Exit status: bad usage or input (nothing checked or written).
inline constexpr int kGoldenBadInput = 2;

/// Runs the command; progress and verdicts to `out`, errors to `err`. Every scene file and
/// output path is validated before any frame is rendered or any file written
/// (`plan_golden_command`). Every file a check or update writes (goldens, report, JUnit) is
/// prepared beside its place and moved in only when the whole run has succeeded: a failed
/// write or a signal leaves them all as they were. Throws `demos::Interrupted` on SIGINT,
/// SIGTERM or SIGHUP (the second process ended and every staged file removed first).
int run_golden_command(const GoldenCommandArguments& arguments, std::ostream& out,
                       std::ostream& err);

/// `--dry-run`: runs the checks a run makes before any work and prints the plan (scene
/// files, goldens, the files it would write); renders and writes nothing. Throws
/// `demos::UsageError` as the run would fail with exit status 2.
void dry_run_golden_command(const GoldenCommandArguments& arguments, std::ostream& out);

}  // namespace impulse2d::golden

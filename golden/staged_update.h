#pragma once
/// @file staged_update.h
/// `golden update` as one transaction: every new golden (PNG and sidecar) is written into a
/// staging folder inside the golden directory (same filesystem), and only when all of them
/// are written does `commit` move them into place, one atomic directory swap per scene
/// folder. A journal written before the first swap lets the next run finish a commit that was
/// killed half-way (roll forward); a staging folder without a journal is removed (roll back).
/// So the golden directory holds the whole old set or the whole new one, and a PNG is never
/// beside another run's sidecar.
///
/// ```
/// <golden dir>/.impulse2d-golden-update/            the staging folder (locked while in use)
/// <golden dir>/.impulse2d-golden-update/<scene>/    the scene folder as it will be
/// <golden dir>/.impulse2d-golden-update/journal.json  {"scenes": [{"name", "inode"}]}: the commit began
/// <golden dir>/.impulse2d-golden-update/.second-process/  the second process's frame (never committed)
/// ```

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The staging folder's name inside a golden directory.
inline constexpr const char* kStagingFolderName = ".impulse2d-golden-update";

/// What `recover_interrupted_update` found and did.
enum class Recovery {
  None,           ///< no staging folder: nothing to do
  RolledBack,     ///< an update stopped before its commit: its staging folder was removed
  RolledForward,  ///< an update stopped during its commit: the commit was finished
  Busy,           ///< another process is updating the directory now: left alone
};

/// Finishes or undoes an update of `golden_dir` that a killed process left (see the file
/// comment); Busy when the staging folder is locked by a running update. Throws `GoldenError`
/// when a move fails.
Recovery recover_interrupted_update(const std::filesystem::path& golden_dir);

/// Where an interrupted update of `golden_dir` would be recovered, in words for a plan, e.g.
/// "an interrupted update's staging folder X (rolled back: it never began its commit)";
/// empty when there is none.
std::string describe_interrupted_update(const std::filesystem::path& golden_dir);

/// One update of one golden directory. Write new goldens under `path()` with the golden
/// directory's layout (`<scene>/<frame>.png` + `.json`), then `commit`. Destroyed without a
/// commit (an exception, a signal), it removes the staging folder: the goldens stay as they
/// were.
class StagedUpdate {
 public:
  /// Recovers an earlier interrupted update, then creates and locks the staging folder.
  /// Throws `GoldenError` when another update holds the directory or the folder cannot be
  /// created.
  explicit StagedUpdate(std::filesystem::path golden_dir);
  /// Removes the staging folder (and the golden directory when this update created it and
  /// it is empty) unless committed.
  ~StagedUpdate();
  StagedUpdate(const StagedUpdate&) = delete;
  StagedUpdate& operator=(const StagedUpdate&) = delete;

  /// The golden directory.
  const std::filesystem::path& golden_dir() const { return golden_dir_; }
  /// The staging folder: where new goldens are written.
  const std::filesystem::path& path() const { return staging_; }
  /// A folder for this run's temporary files (the second process's frame); never committed.
  std::filesystem::path scratch() const { return staging_ / ".second-process"; }

  /// Completes each staged scene folder with the files of the golden scene folder that it
  /// does not replace (hard links), writes the journal, and swaps each scene folder into
  /// place; the old ones are removed. `after_swap` (tests) is called after each swap with
  /// the scene folder's name. A failed swap undoes the swaps before it and throws
  /// `GoldenError`. Returns how many scene folders were replaced or added.
  std::size_t commit(const std::function<void(const std::string&)>& after_swap = nullptr);

 private:
  std::filesystem::path golden_dir_;
  std::filesystem::path staging_;
  /// Folders this update created for the golden directory, deepest first (removed again,
  /// when still empty, by an update that did not commit).
  std::vector<std::filesystem::path> created_;
  int lock_ = -1;
  bool committed_ = false;
};

}  // namespace impulse2d::golden

#pragma once
/// @file lab_output.h
/// A lab run's output folder written as one unit: every file (CSV, charts, stability map and
/// sheets) goes into a staging folder inside it, on the same filesystem, and is moved into
/// place only when everything succeeded. A failure or a signal removes the staging folder and
/// leaves the folder as it was. A folder holding another run's results is refused unless the
/// run is asked to replace them (`--clean`); shards of one sweep (`lab_shard_K_of_N.csv`, same
/// N) share a folder.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "frames/output_guard.h"
#include "frames/output_staging.h"

namespace impulse2d::lab {

/// The lab results in `directory` that a run writing `own_files` (names in the folder: "lab.csv",
/// "charts", "lab_shard_2_of_4.csv", ...) would mix with: every lab output there except shard
/// CSVs of this sweep that the run does not write itself (`sweep_shards` N > 1: the shards of
/// N; 0: any shard CSV, for `lab merge`, whose inputs they are; 1: none). Sorted.
std::vector<std::string> other_runs_results(const std::filesystem::path& directory,
                                            const std::vector<std::string>& own_files,
                                            int sweep_shards);

/// Checks before any work that `directory` can receive the run's output: it is a folder (or
/// can be created: its nearest existing ancestor is a writable folder), writable, and holds no
/// other run's results unless `clean`. Throws `demos::UsageError` naming `option` and the path.
void check_output_directory(const std::filesystem::path& directory,
                            const std::vector<std::string>& other_results, bool clean,
                            const std::string& option);

/// Checks before any work that the file `file` can be written: not a folder, and its folder
/// exists as a writable folder or can be created. Throws `demos::UsageError` naming `option`.
void check_output_file(const std::filesystem::path& file, const std::string& option);

/// One run's output folder as a transaction.
class OutputTransaction {
 public:
  /// Creates `directory` if missing (removed again unless committed) and the staging folder
  /// inside it. `replaced` are entries of the folder removed when the run commits (`--clean`).
  OutputTransaction(const std::filesystem::path& directory, std::vector<std::string> replaced);
  /// Removes the staging folder with what it holds and, unless committed, what was created.
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// Where the run writes: the staging folder (its files keep their names relative to it).
  const std::filesystem::path& staging() const { return staging_->path(); }
  /// The staged `name` ("lab.csv", "charts/x.png") as it will be named after `commit`.
  std::filesystem::path final_path(const std::string& name) const { return directory_ / name; }
  /// `message` with the staging folder's path replaced by the output folder's, so errors name
  /// the files the user asked for.
  std::string in_output_terms(const std::string& message) const;
  /// Moves the replaced entries aside and every staged entry into the folder; on a failure
  /// half-way everything is moved back and `std::runtime_error` names the entry and the reason.
  /// Throws `demos::Interrupted` (nothing moved) when a signal arrived before.
  void commit();

 private:
  std::filesystem::path directory_;
  std::vector<std::string> replaced_;
  demos::OutputGuard guard_;  // declared before the staging folder: destroyed after it
  std::unique_ptr<demos::StagingDirectory> staging_;
};

}  // namespace impulse2d::lab

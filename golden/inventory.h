#pragma once
/// @file inventory.h
/// What golden_images/ holds, so a suite can report goldens no test uses and files that
/// lack their partner (a PNG without a sidecar or the reverse).

#include <filesystem>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The goldens below a directory, by name ("<scene>/<golden>", '/'-separated, sorted).
struct GoldenInventory {
  std::vector<std::string> goldens;          ///< names with both a .png and a .json
  std::vector<std::string> missing_sidecar;  ///< names with a .png but no .json
  std::vector<std::string> missing_image;    ///< names with a .json but no .png
};

/// Scans `golden_dir` recursively. A directory that does not exist is empty. Throws
/// `GoldenError` when the directory cannot be read.
GoldenInventory scan_goldens(const std::filesystem::path& golden_dir);

/// The names in `goldens` that are not in `used`, sorted; a renderer baseline
/// ("<name>@<renderer key>") counts as used when its golden is.
std::vector<std::string> unused_goldens(const std::vector<std::string>& goldens,
                                        const std::vector<std::string>& used);

}  // namespace impulse2d::golden

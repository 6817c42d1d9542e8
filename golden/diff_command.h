#pragma once
/// @file diff_command.h
/// `impulse2d diff a.png b.png [--out DIR]`: compares two PNG files as the golden suite does
/// (exact match on decoded RGBA first, metrics only on a mismatch) and, with an output
/// directory, leaves the difference as images, metrics.json and an HTML report.

#include <iosfwd>
#include <string>

#include "golden/diff_limits.h"

namespace impulse2d::golden {

/// Exit status of `run_diff_command`: the images match (exactly or within tolerance).
inline constexpr int kDiffSame = 0;
/// Exit status of `run_diff_command`: the images differ beyond tolerance or in size.
inline constexpr int kDiffDiffers = 1;
/// Exit status of `run_diff_command`: an input could not be read or an output written.
inline constexpr int kDiffError = 2;

/// Compares `expected_png` (a) with `actual_png` (b) under the tolerance `limits` describe
/// (strict by default) and prints one verdict paragraph to `out`; when both PNGs carry the
/// golden tools' metadata (png_text.h), a second line says what they were and whether the
/// physics state or only the pixels differ. When they are not an exact match and `out_dir`
/// is not empty, writes into it expected.png, actual.png, diff.png and heatmap.png (the last
/// two when the sizes agree), metrics.json and index.html, and prints the report's path.
/// Errors go to `err`, naming the file or option. Returns kDiffSame, kDiffDiffers or
/// kDiffError (also for limits out of range).
int run_diff_command(const std::string& expected_png, const std::string& actual_png,
                     const std::string& out_dir, std::ostream& out, std::ostream& err,
                     const DiffLimits& limits = DiffLimits{});

}  // namespace impulse2d::golden

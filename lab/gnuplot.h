#pragma once
/// @file gnuplot.h
/// Drawing charts with gnuplot (Debian's gnuplot-nox): a script is written to a temporary file,
/// gnuplot draws into a temporary PNG, which is renamed into place (nothing half-written).

#include <string>

namespace impulse2d::lab {

/// True when a `gnuplot` program is on PATH.
bool gnuplot_available();

/// Runs `script` (which must draw with `set output OUTPUT`, the placeholder being replaced by
/// the temporary file's path) and renames the result to `png_path`. Throws
/// `std::runtime_error` with gnuplot's complaint when it fails.
void run_gnuplot(const std::string& script, const std::string& png_path);

/// `text` escaped for a double-quoted gnuplot string (scripts use `noenhanced` text).
std::string gnuplot_text(const std::string& text);

}  // namespace impulse2d::lab

#pragma once
/// @file gnuplot.h
/// Drawing charts with gnuplot (Debian's gnuplot-nox), started without a shell (an argument
/// vector; no path the user gives appears in a command line or in the script): the script goes
/// to its standard input, it draws to its standard output, which is a temporary PNG beside the
/// chart, renamed into place when gnuplot succeeded (nothing half-written).

#include <string>

namespace impulse2d::lab {

/// True when a `gnuplot` program is on PATH.
bool gnuplot_available();

/// Runs `script` (which must draw with the line `set output OUTPUT`, which becomes `set output`:
/// standard output) and renames the result to `png_path`. Throws `std::runtime_error`
/// "gnuplot failed drawing <png_path>: <reason>", the reason being why it could not start, or
/// its exit status (or signal) and its complaint.
void run_gnuplot(const std::string& script, const std::string& png_path);

/// `text` escaped for a double-quoted gnuplot string (scripts use `noenhanced` text).
std::string gnuplot_text(const std::string& text);

}  // namespace impulse2d::lab

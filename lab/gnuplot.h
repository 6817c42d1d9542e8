#pragma once
/// @file gnuplot.h
/// Drawing charts with gnuplot (Debian's gnuplot-nox), started without a shell (an argument
/// vector; no path the user gives appears in a command line or in the script): the script goes
/// to its standard input, it draws to its standard output, a pipe the program reads; the PNG is
/// checked whole and written through a temporary file renamed into place (nothing half-written,
/// and a failed write names the file and the system's reason).

#include <string>

namespace impulse2d::lab {

/// True when a `gnuplot` program is on PATH.
bool gnuplot_available();

/// Runs `script` (which must draw with the line `set output OUTPUT`, which becomes `set output`:
/// standard output) and writes the PNG to `png_path`. Throws `std::runtime_error`
/// "gnuplot failed drawing <png_path>: <reason>", the reason being why it could not start, its
/// exit status (or signal) and its complaint on stderr, a broken PNG, or why the file could not
/// be written. On SIGINT, SIGTERM or SIGHUP gnuplot is ended (SIGTERM) and
/// `demos::Interrupted` thrown.
void run_gnuplot(const std::string& script, const std::string& png_path);

/// `text` escaped for a double-quoted gnuplot string (scripts use `noenhanced` text).
std::string gnuplot_text(const std::string& text);

}  // namespace impulse2d::lab

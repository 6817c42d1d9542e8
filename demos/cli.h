#pragma once
/// @file cli.h
/// The `impulse2d` command line (CLI11): no arguments renders the default demo into out/;
/// subcommands list, render, trace, sheet, diff, lab (and lab merge) and tune; --help everywhere.

namespace impulse2d::demos {

/// Runs the program with `argv`. Returns the exit status: 0 success, 1 runtime failure
/// (unwritable output, renderer, ffmpeg), 2 bad usage (unknown scene or option, invalid
/// scene file, parameter or frame range).
int run_cli(int argc, char** argv);

}  // namespace impulse2d::demos

#pragma once
/// @file cli.h
/// The `impulse2d` command line (CLI11): no arguments renders the default demo into out/;
/// subcommands list, render, trace, sheet, diff, golden, lab (and lab merge) and tune;
/// --help everywhere, --version, --quiet and --dry-run.

namespace impulse2d::demos {

/// Runs the program with `argv`. Returns the exit status: 0 success, 1 runtime failure
/// (unwritable output, renderer, ffmpeg; `golden check`: a golden failed), 2 bad usage
/// (unknown command, option, scene, invalid scene file, parameter or frame range), 128 + N
/// after signal N; `diff` alone: 0 the frames match, 1 they differ, 2 trouble. Every error
/// message starts with "impulse2d:".
int run_cli(int argc, char** argv);

}  // namespace impulse2d::demos

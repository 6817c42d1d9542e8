/// @file command_diff.cpp
/// `impulse2d diff`: two PNG frames compared as the golden suite compares them.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "app/command.h"
#include "golden/diff_command.h"
#include "golden/diff_limits.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d diff`.
struct DiffArguments {
  std::string expected;          ///< the reference PNG (a)
  std::string actual;            ///< the PNG to check (b)
  std::string out;               ///< report directory on a mismatch ("": none)
  golden::DiffLimits limits;     ///< how much may differ
};

}  // namespace

Command add_diff_command(CLI::App& program, const ProgramOptions&) {
  auto diff = std::make_shared<DiffArguments>();
  CLI::App* command = program.add_subcommand(
      "diff",
      "compare two PNG frames as the golden suite does (exact RGBA match first, metrics on a "
      "mismatch; the frames' metadata says whether the physics or only the pixels differ)");
  command->footer(
      "Exit status (as cmp and diff): 0 the frames match, 1 they differ, 2 trouble (bad usage, "
      "an unreadable input, an unwritable --out).");
  command->add_option("expected", diff->expected, "the reference PNG (a)")->required();
  command->add_option("actual", diff->actual, "the PNG to check (b)")->required();
  command->add_option("--out,-o", diff->out,
                      "on a mismatch, write expected/actual/diff/heatmap PNGs, "
                      "metrics.json and index.html into this directory");
  command->add_option("--max-diff-pixels", diff->limits.max_diff_pixels,
                      "pass when at most this many pixels differ (default: none may)");
  command->add_option("--max-diff-ratio", diff->limits.max_diff_ratio,
                      "pass when at most this fraction (0..1) of pixels differs");
  command->add_option("--threshold", diff->limits.threshold,
                      "a pixel differs when a channel changes by more than this (0..255)")
      ->capture_default_str();
  command->add_option("--mask", diff->limits.masks,
                      "x,y,w,h: ignore this rectangle (pixels from the top-left; "
                      "one rectangle per flag, repeatable)")
      ->take_all()
      ->allow_extra_args(false);

  Command result;
  result.parser = command;
  result.own_exit_status = true;  // 0 match, 1 differ, 2 trouble (as cmp and diff)
  result.run = [diff](std::ostream& out) {
    return golden::run_diff_command(diff->expected, diff->actual, diff->out, out, std::cerr,
                                    diff->limits);
  };
  return result;
}

}  // namespace impulse2d::demos

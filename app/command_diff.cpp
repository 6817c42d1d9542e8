/// @file command_diff.cpp
/// `impulse2d diff`: two PNG frames compared as the golden suite compares them.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "app/command.h"
#include "app/strict_number_check.h"
#include "golden/diff_command.h"
#include "golden/diff_limits.h"
#include "golden/tolerance.h"
#include "image/png.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

/// `impulse2d diff`.
struct DiffArguments {
  std::string expected;          ///< the reference PNG (a)
  std::string actual;            ///< the PNG to check (b)
  std::string out;               ///< report directory on a mismatch ("": none)
  golden::DiffLimits limits;     ///< how much may differ
};

/// What `diff` would compare, for --dry-run: the limits and both PNGs read and checked as the
/// run reads them (the same messages), then the plan. Throws `UsageError` ("diff: ...") where
/// the run would exit with status 2.
void print_diff_plan(const DiffArguments& diff, std::ostream& out) {
  golden::Tolerance tolerance;
  image::Image expected;
  image::Image actual;
  try {
    tolerance = golden::tolerance_from_limits(diff.limits, "command-line limits");
    expected = image::load_png(diff.expected);
    actual = image::load_png(diff.actual);
  } catch (const std::exception& error) {
    throw UsageError(std::string("diff: ") + error.what());
  }
  out << "dry run: diff " << diff.expected << " (" << expected.width << "x" << expected.height
      << ") with " << diff.actual << " (" << actual.width << "x" << actual.height << ")\n"
      << "  tolerance: "
      << (tolerance.is_strict() ? std::string("strict (any differing pixel fails)")
                                : "threshold " + std::to_string(tolerance.max_channel_delta) +
                                      ", at most " + std::to_string(tolerance.max_differing_pixels) +
                                      " pixels, " + std::to_string(tolerance.masks.size()) + " masks")
      << "\n";
  if (!diff.out.empty()) {
    out << "  on a mismatch writes: " << diff.out
        << "/ (expected, actual, diff and heatmap PNGs, metrics.json, index.html)\n";
  }
  out << "nothing was compared or written\n";
}

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
                      "pass when at most this many pixels differ (default: none may)")
      ->check(whole_number_check());
  command->add_option("--max-diff-ratio", diff->limits.max_diff_ratio,
                      "pass when at most this fraction (0..1) of pixels differs")
      ->check(decimal_check());
  command->add_option("--threshold", diff->limits.threshold,
                      "a pixel differs when a channel changes by more than this (0..255)")
      ->capture_default_str()
      ->check(whole_number_check());
  command->add_option("--mask", diff->limits.masks,
                      "x,y,w,h: ignore this rectangle (pixels from the top-left; "
                      "one rectangle per flag, repeatable)")
      ->take_all()
      ->allow_extra_args(false);

  Command result;
  result.parser = command;
  result.own_exit_status = true;  // 0 match, 1 differ, 2 trouble (as cmp and diff)
  result.dry_run = [diff](std::ostream& out) { print_diff_plan(*diff, out); };
  result.run = [diff](std::ostream& out) {
    return golden::run_diff_command(diff->expected, diff->actual, diff->out, out, std::cerr,
                                    diff->limits);
  };
  return result;
}

}  // namespace impulse2d::demos

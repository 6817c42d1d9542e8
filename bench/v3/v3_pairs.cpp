/// @file v3_pairs.cpp
#include "bench/v3/v3_pairs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace impulse2d::bench_v3 {
namespace {

std::string decimals(double value, int places) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", places, value);
  return text;
}

const char* yes_no(bool value) { return value ? "yes" : "no"; }

// The median over the rounds of the runs' median ms per step.
double median_ms(const std::vector<RunResult>& runs) {
  std::vector<double> values;
  for (const RunResult& run : runs) values.push_back(run.median_ms);
  return median(values);
}

void stability_row(std::ostream& out, const std::string& label, const RunResult& run, bool pyramids) {
  const compare::Stability& figures = run.stability;
  out << "| " << label << " | ";
  if (pyramids) {
    out << decimals(figures.sag, 3) << " | " << decimals(figures.side, 3) << " | " << figures.moved;
  } else {
    out << figures.out;
  }
  out << " | " << figures.non_finite << " | " << decimals(figures.depth, 4) << " |\n";
}

}  // namespace

PairSummary summarize_pairs(const std::vector<double>& ratios) {
  const Spread spread = spread_of(ratios);
  PairSummary summary;
  summary.ratios = ratios;
  summary.median = spread.median;
  summary.min = spread.min;
  summary.max = spread.max;
  summary.all_below_one = summary.max < 1.0;
  summary.median_meets_goal = summary.median <= goal_ratio;
  return summary;
}

std::vector<double> pair_ratios(const WidthSeries& series) {
  if (series.ours_runs.size() != series.theirs_runs.size()) {
    throw std::invalid_argument(series.ours + " and " + series.theirs + " ran a different number of rounds");
  }
  std::vector<double> ratios;
  for (std::size_t r = 0; r < series.ours_runs.size(); ++r) {
    const double theirs = series.theirs_runs[r].median_ms;
    ratios.push_back(theirs > 0.0 ? series.ours_runs[r].median_ms / theirs : -1.0);
  }
  return ratios;
}

void write_report(std::ostream& out, const Report& report, bool markdown) {
  const std::string title = "impulse2d beside Box2D v3 (commit " + report.commit + ") at equal vector width";
  if (markdown) {
    out << "## " << title << "\n\n";
  } else {
    out << title << "\n" << std::string(title.size(), '=') << "\n";
  }
  const char* const end_of_line = markdown ? "  \n" : "\n";
  out << "Box2D v3 commit: " << report.commit << end_of_line
      << "machine: " << report.machine << end_of_line
      << "load average (1, 5, 15 min) before / after: " << report.load << end_of_line
      << "command: `" << report.command << "`" << end_of_line
      << "rounds: " << report.rounds
      << ", each alternating impulse2d 4 lanes, v3 SSE2, impulse2d 8 lanes, v3 AVX2; one thread, "
         "1/60 s, 4 sub-steps, sleeping off, gravity -10 m/s^2; ms = median CPU time of a step; "
         "ratio = impulse2d / v3 of one round's pair (below 1: impulse2d faster); goal: median <= "
      << decimals(goal_ratio, 1) << " and every pair below 1\n";
  for (const SceneSeries& scene : report.scenes) {
    const std::string heading = scene.scene + " (" + std::to_string(scene.bodies) + " bodies, " +
                                std::to_string(scene.steps) + " steps timed after " +
                                std::to_string(scene.warmup) + " untimed)";
    out << "\n" << (markdown ? "### " : "") << heading << " - Box2D v3 " << report.commit << "\n\n";
    out << "| pair (ours / v3) | ours ms | v3 ms | ratio of each round | median | [min-max] | "
           "all below 1 | median <= 0.9 |\n"
        << "|---|---:|---:|---|---:|---|---|---|\n";
    for (const WidthSeries& width : scene.widths) {
      out << "| " << width.ours << " / " << width.theirs << " | ";
      if (!width.skipped.empty()) {
        out << "| | skipped: " << width.skipped << " | | | | |\n";
        continue;
      }
      const PairSummary summary = summarize_pairs(pair_ratios(width));
      std::string each;
      for (const double ratio : summary.ratios) each += (each.empty() ? "" : " ") + decimals(ratio, 3);
      out << decimals(median_ms(width.ours_runs), 3) << " | " << decimals(median_ms(width.theirs_runs), 3)
          << " | " << each << " | " << decimals(summary.median, 3) << " | [" << decimals(summary.min, 3)
          << "-" << decimals(summary.max, 3) << "] | " << yes_no(summary.all_below_one) << " | "
          << yes_no(summary.median_meets_goal) << " |\n";
    }
    const bool pyramids = scene.judge == compare::Judge::Pyramids;
    out << "\n| stability at the end (first round) | "
        << (pyramids ? "sag m | side m | moved > 0.1 m or 5 deg" : "balls out of the pit")
        << " | non-finite | deepest overlap m |\n"
        << (pyramids ? "|---|---:|---:|---:|---:|---:|\n" : "|---|---:|---:|---:|\n");
    for (const WidthSeries& width : scene.widths) {
      if (!width.skipped.empty()) continue;
      stability_row(out, width.ours, width.ours_runs.front(), pyramids);
      stability_row(out, width.theirs, width.theirs_runs.front(), pyramids);
    }
  }
}

}  // namespace impulse2d::bench_v3

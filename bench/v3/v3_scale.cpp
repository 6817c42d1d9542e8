/// @file v3_scale.cpp
#include "bench/v3/v3_scale.h"

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

// "median [min-max]" of one engine's per-body costs.
std::string cost_cell(const std::vector<double>& costs) {
  const Spread spread = spread_of(costs);
  return decimals(spread.median, 3) + " [" + decimals(spread.min, 3) + "-" + decimals(spread.max, 3) + "]";
}

// "each round's; median" of per-round ratios.
std::string rounds_cell(const std::vector<double>& ratios) {
  std::string cell;
  for (const double ratio : ratios) cell += (cell.empty() ? "" : " ") + decimals(ratio, 2);
  return cell + "; " + decimals(spread_of(ratios).median, 2);
}

std::string growth_text(const std::vector<double>& growth) {
  const Spread spread = spread_of(growth);
  return decimals(spread.median, 2) + "x [" + decimals(spread.min, 2) + "-" + decimals(spread.max, 2) + "]";
}

void stability_row(std::ostream& out, const std::string& label, const RunResult& run) {
  const compare::Stability& figures = run.stability;
  out << "| " << label << " | " << decimals(figures.sag, 3) << " | " << decimals(figures.side, 3) << " | "
      << figures.moved << " | " << figures.non_finite << " | " << decimals(figures.depth, 4) << " |\n";
}

void write_width(std::ostream& out, const ScaleReport& report, const ScaleWidth& width, bool markdown) {
  out << "\n" << (markdown ? "### " : "") << width.ours << " / " << width.theirs << " - Box2D v3 "
      << report.commit << "\n\n";
  if (!width.skipped.empty()) {
    out << "skipped: " << width.skipped << "\n";
    return;
  }
  if (width.points.empty()) throw std::invalid_argument(width.ours + ": no sizes measured");
  const ScalePoint& first = width.points.front();
  const std::vector<double> ours_first = per_body_costs(first.ours_runs, first.bodies);
  const std::vector<double> theirs_first = per_body_costs(first.theirs_runs, first.bodies);
  const std::string from = std::to_string(first.bodies);
  out << "| bodies | " << width.ours << " µs/body/step | growth from " << from << " (each round; median) | "
      << width.theirs << " µs/body/step | growth from " << from << " (each round; median) | "
      << "ours / v3 (each round; median) | heap B/body (ours / v3) |\n"
      << "|---:|---|---|---|---|---|---:|\n";
  std::vector<double> ours_growth;
  std::vector<double> theirs_growth;
  for (const ScalePoint& point : width.points) {
    if (point.ours_runs.size() != point.theirs_runs.size() || point.ours_runs.size() != ours_first.size()) {
      throw std::invalid_argument(width.ours + " / " + width.theirs + " ran a different number of rounds at " +
                                  std::to_string(point.bodies) + " bodies");
    }
    const std::vector<double> ours = per_body_costs(point.ours_runs, point.bodies);
    const std::vector<double> theirs = per_body_costs(point.theirs_runs, point.bodies);
    ours_growth = per_round_ratios(ours, ours_first);
    theirs_growth = per_round_ratios(theirs, theirs_first);
    out << "| " << point.bodies << " | " << cost_cell(ours) << " | " << rounds_cell(ours_growth) << " | "
        << cost_cell(theirs) << " | " << rounds_cell(theirs_growth) << " | "
        << rounds_cell(per_round_ratios(ours, theirs)) << " | "
        << decimals(median(heap_per_body(point.ours_runs, point.bodies)), 0) << " / "
        << decimals(median(heap_per_body(point.theirs_runs, point.bodies)), 0) << " |\n";
  }
  const ScalePoint& last = width.points.back();
  out << "\ngrowth of the cost per body from " << from << " to " << last.bodies
      << " bodies, median of the rounds [min-max]: " << width.ours << " " << growth_text(ours_growth) << ", "
      << width.theirs << " " << growth_text(theirs_growth) << "; " << width.ours << " below "
      << decimals(scale_goal_growth, 1) << "x (issue 33, goal 4): "
      << (spread_of(ours_growth).median < scale_goal_growth ? "yes" : "no") << "\n";
  out << "\n| stability at " << last.bodies
      << " bodies (first round) | sag m | side m | moved > 0.1 m or 5 deg | non-finite | deepest overlap m |\n"
      << "|---|---:|---:|---:|---:|---:|\n";
  stability_row(out, width.ours, last.ours_runs.front());
  stability_row(out, width.theirs, last.theirs_runs.front());
}

}  // namespace

double micros_per_body(double ms_per_step, int bodies) {
  return 1e3 * ms_per_step / static_cast<double>(std::max(1, bodies));
}

std::vector<double> per_round_ratios(const std::vector<double>& numerators,
                                     const std::vector<double>& denominators) {
  if (numerators.size() != denominators.size()) {
    throw std::invalid_argument("per-round ratios of " + std::to_string(numerators.size()) + " and " +
                                std::to_string(denominators.size()) + " rounds");
  }
  std::vector<double> ratios;
  for (std::size_t r = 0; r < numerators.size(); ++r) {
    if (!(denominators[r] > 0.0)) throw std::invalid_argument("a round's denominator is not positive");
    ratios.push_back(numerators[r] / denominators[r]);
  }
  return ratios;
}

std::vector<double> per_body_costs(const std::vector<RunResult>& runs, int bodies) {
  std::vector<double> costs;
  for (const RunResult& run : runs) costs.push_back(micros_per_body(run.median_ms, bodies));
  return costs;
}

std::vector<double> heap_per_body(const std::vector<RunResult>& runs, int bodies) {
  std::vector<double> bytes;
  for (const RunResult& run : runs) bytes.push_back(run.heap_bytes / static_cast<double>(std::max(1, bodies)));
  return bytes;
}

void write_scale_report(std::ostream& out, const ScaleReport& report, bool markdown) {
  const std::string title = "impulse2d beside Box2D v3 (commit " + report.commit +
                            ") on the scaling series, per body, at equal vector width";
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
      << "rounds: " << report.rounds << ", each running every size in turn, at each alternating impulse2d "
         "4 lanes, v3 SSE2, impulse2d 8 lanes, v3 AVX2; bench_compare's scaling series (pyramids of "
         "55 boxes, 20 to a ground); "
      << report.steps << " steps timed after " << report.warmup
      << " untimed; one thread, 1/60 s, 4 sub-steps, sleeping off, gravity -10 m/s^2; µs/body/step = "
         "median CPU time of a step / bodies, median over the rounds [min-max]; growth = a round's "
         "µs/body/step over the same round's at the smallest size; ours / v3 = a round's pair "
         "(below 1: impulse2d faster); heap B/body = growth of the bytes malloc has handed out "
         "(glibc mallinfo2) from before the world was built to after its last step, over bodies, "
         "median over the rounds\n";
  for (const ScaleWidth& width : report.widths) write_width(out, report, width, markdown);
}

}  // namespace impulse2d::bench_v3

/// @file lab_chart.cpp
#include "lab/lab_chart.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "lab/gnuplot.h"
#include "lab/label_layout.h"

namespace impulse2d::lab {
namespace {

// Canvas and plot area, pixels (the plot area is pinned with `set margins at screen`).
constexpr double canvas_width = 1100.0;
constexpr double canvas_height = 800.0;
constexpr double plot_left = 90.0, plot_right = 1080.0, plot_bottom = 70.0, plot_top = 700.0;

/// A point of the chart in data and pixel coordinates.
struct ChartPoint {
  const LabResult* result;
  double cost, error;  // as drawn (errors of 0 and infinity moved to the floor / ceiling)
  double px, py;
};

std::string format(double value) {
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

std::string short_number(double value) {
  std::ostringstream text;
  text.precision(2);
  text << value;
  return text.str();
}

void draw_one(const std::string& scenario, const std::vector<const LabResult*>& rows,
              const std::string& png_path) {
  double cost_min = 1e300, cost_max = 0.0, error_min = 1e300, error_max = 0.0;
  const double threshold = rows.front()->threshold;
  const std::string unit = rows.front()->unit;
  for (const LabResult* row : rows) {
    cost_min = std::min(cost_min, row->us_per_simulated_second);
    cost_max = std::max(cost_max, row->us_per_simulated_second);
    if (row->error > 0.0 && std::isfinite(row->error)) {
      error_min = std::min(error_min, row->error);
      error_max = std::max(error_max, row->error);
    }
  }
  if (error_max == 0.0) error_min = error_max = threshold;
  error_min = std::min(error_min, threshold);
  error_max = std::max(error_max, threshold);
  const double floor = error_min / 3.0;       // where errors of exactly 0 are drawn
  const double ceiling = error_max * 3.0;     // where diverged runs are drawn
  const double x_low = cost_min / 1.6, x_high = cost_max * 1.6;
  const double y_low = floor / 2.0, y_high = ceiling * 2.0;
  const auto to_px = [&](double cost) {
    return plot_left + (std::log(cost / x_low) / std::log(x_high / x_low)) * (plot_right - plot_left);
  };
  const auto to_py = [&](double error) {
    return plot_bottom + (std::log(error / y_low) / std::log(y_high / y_low)) * (plot_top - plot_bottom);
  };

  std::vector<ChartPoint> points;
  for (const LabResult* row : rows) {
    ChartPoint point{row, row->us_per_simulated_second, row->error, 0, 0};
    if (!std::isfinite(point.error)) point.error = ceiling;
    if (point.error <= 0.0) point.error = floor;
    point.px = to_px(point.cost);
    point.py = to_py(point.error);
    points.push_back(point);
  }
  std::vector<LabelRequest> requests;
  for (const ChartPoint& point : points) {
    const LabResult& r = *point.result;
    int priority = 0;
    if (r.pareto) priority = 2;
    if (r.method.engine != Engine::Impulse2d) priority = 3;
    if (r.recommended) priority = 4;
    requests.push_back({point.px, point.py, method_label(r.method), priority});
  }
  const std::vector<PlacedLabel> labels =
      layout_labels(requests, plot_left, plot_right, plot_bottom, plot_top, 5.6, 11.0, 7.0);
  int unlabelled = 0;
  for (const PlacedLabel& label : labels) unlabelled += label.placed ? 0 : 1;

  std::ostringstream gp;
  gp << "set terminal pngcairo size " << canvas_width << "," << canvas_height
     << " font 'DejaVu Sans,9' noenhanced\n"
     << "set output OUTPUT\n"
     << "set lmargin at screen " << plot_left / canvas_width << "\n"
     << "set rmargin at screen " << plot_right / canvas_width << "\n"
     << "set bmargin at screen " << plot_bottom / canvas_height << "\n"
     << "set tmargin at screen " << plot_top / canvas_height << "\n"
     << "set logscale xy\nset format y '%g'\nset format x '%g'\n"
     << "set xrange [" << format(x_low) << ":" << format(x_high) << "]\n"
     << "set yrange [" << format(y_low) << ":" << format(y_high) << "]\n"
     << "set grid xtics ytics mxtics mytics lc rgb '#e6e6e6'\n"
     << "set xlabel 'cost: microseconds of CPU per simulated second (median of interleaved repeats)'\n"
     << "set ylabel \"" << gnuplot_text("error (" + unit + ")") << "\"\n"
     << "set label 1000 \"" << gnuplot_text(scenario + ": error against cost; " +
                                      std::to_string(unlabelled) +
                                      " crowded points unlabelled (all are in the CSV); errors of 0 "
                                      "drawn at " + short_number(floor) + ", diverged runs at " +
                                      short_number(ceiling))
     << "\" at screen 0.01, screen 0.975 left font ',10'\n"
     << "set key at screen 0.5, screen 0.945 center top horizontal maxrows 2 samplen 2 font ',9'\n"
     << "set arrow from graph 0, first " << format(threshold) << " to graph 1, first "
     << format(threshold) << " nohead dt 2 lw 1.5 lc rgb '#555555'\n"
     << "set label \"" << gnuplot_text("pass threshold " + short_number(threshold) + " " + unit)
     << "\" at graph 0.01, first " << format(threshold * 1.15) << " tc rgb '#555555'\n";
  for (const PlacedLabel& label : labels) {
    if (!label.placed) continue;
    gp << "set label \"" << gnuplot_text(label.text) << "\" at screen "
       << format(label.x / canvas_width) << ", screen " << format(label.y / canvas_height)
       << " left font ',8' tc rgb '#333333'\n";
  }
  const auto block = [&](const std::string& name, auto keep) {
    gp << "$" << name << " << EOD\n";
    int count = 0;
    for (const ChartPoint& point : points) {
      if (!keep(*point.result)) continue;
      gp << format(point.cost) << " " << format(point.error) << "\n";
      ++count;
    }
    if (count == 0) gp << "NaN NaN\n";
    gp << "EOD\n";
  };
  const auto own = [](const LabResult& r) { return r.method.engine == Engine::Impulse2d; };
  block("pass", [&](const LabResult& r) { return own(r) && r.pass; });
  block("fail", [&](const LabResult& r) { return own(r) && !r.pass && std::isfinite(r.error); });
  block("diverged", [&](const LabResult& r) { return own(r) && !std::isfinite(r.error); });
  block("box2d", [](const LabResult& r) { return r.method.engine == Engine::Box2d; });
  block("chipmunk", [](const LabResult& r) { return r.method.engine == Engine::Chipmunk; });
  block("recommended", [](const LabResult& r) { return r.recommended; });
  // The front, cheapest first (points are already in cost order after sorting below).
  std::vector<ChartPoint> front;
  for (const ChartPoint& point : points)
    if (point.result->pareto) front.push_back(point);
  std::sort(front.begin(), front.end(),
            [](const ChartPoint& a, const ChartPoint& b) { return a.cost < b.cost; });
  gp << "$front << EOD\n";
  for (const ChartPoint& point : front) gp << format(point.cost) << " " << format(point.error) << "\n";
  if (front.empty()) gp << "NaN NaN\n";
  gp << "EOD\n";
  gp << "plot $front using 1:2 with steps lw 2 lc rgb '#009E73' title 'Pareto front', \\\n"
     << "  $pass using 1:2 with points pt 7 ps 1.0 lc rgb '#0072B2' title 'impulse2d: passes', \\\n"
     << "  $fail using 1:2 with points pt 6 ps 1.0 lc rgb '#D55E00' title 'impulse2d: fails', \\\n"
     << "  $diverged using 1:2 with points pt 2 ps 1.2 lc rgb '#D55E00' title 'diverged', \\\n"
     << "  $box2d using 1:2 with points pt 9 ps 1.6 lc rgb '#CC79A7' title 'Box2D 2.4.1 (8/3)', \\\n"
     << "  $chipmunk using 1:2 with points pt 5 ps 1.4 lc rgb '#E69F00' title 'Chipmunk 7 (10, debug build)', \\\n"
     << "  $recommended using 1:2 with points pt 3 ps 3.0 lw 2 lc rgb '#000000' title 'recommended: cheapest that passes'\n";
  run_gnuplot(gp.str(), png_path);
}

}  // namespace

std::vector<std::string> draw_lab_charts(const std::vector<LabResult>& results,
                                         const std::string& directory) {
  std::map<std::string, std::vector<const LabResult*>> by_scenario;
  for (const LabResult& result : results) by_scenario[result.scenario].push_back(&result);
  std::vector<std::string> written;
  for (const auto& [scenario, rows] : by_scenario) {
    const std::string path = directory + "/" + scenario + ".png";
    draw_one(scenario, rows, path);
    written.push_back(path);
  }
  return written;
}

}  // namespace impulse2d::lab

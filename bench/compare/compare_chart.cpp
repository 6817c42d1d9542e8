/// @file compare_chart.cpp
#include "bench/compare/compare_chart.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lab/gnuplot.h"

namespace impulse2d::compare {

std::string write_scaling_chart(const std::string& directory,
                                const std::vector<Contender>& contenders,
                                const std::vector<SceneResult>& results, std::string& why) {
  std::ostringstream data;
  data << "bodies";
  for (const Contender& contender : contenders) data << "," << contender.label;
  data << "\n";
  int points = 0;
  int fewest = 0, most = 0;
  std::string steps;
  for (const SceneResult& result : results) {
    if (!result.scaling) continue;
    ++points;
    fewest = fewest == 0 ? result.bodies : std::min(fewest, result.bodies);
    most = std::max(most, result.bodies);
    steps = std::to_string(result.steps);
    data << result.bodies;
    for (const Outcome& outcome : result.outcomes) {
      data << ",";
      if (outcome.ran) data << outcome.ms_per_step;  // an empty field: left out at this size
    }
    data << "\n";
  }
  if (points == 0) {
    why = "no scaling series was run";
    return "";
  }
  const std::filesystem::path csv_path = std::filesystem::absolute(std::filesystem::path(directory) / "scaling.csv");
  {
    std::ofstream file(csv_path, std::ios::binary | std::ios::trunc);
    if (!file) throw std::runtime_error("cannot write " + csv_path.string());
    file << data.str();
  }
  if (!lab::gnuplot_available()) {
    why = "gnuplot is not installed (apt-get install gnuplot-nox): " + csv_path.string() + " holds the series";
    return "";
  }
  std::ostringstream gp;
  gp << "set terminal pngcairo size 900,620 noenhanced font ',11'\n"
     << "set output OUTPUT\n"
     << "set datafile separator ','\n"
     << "set datafile missing ''\n"
     << "set logscale xy\nset format x '%g'\nset format y '%g'\n"
     << "set xrange [" << 0.7 * fewest << ":" << 1.4 * most << "]\n"
     << "set grid xtics ytics mxtics mytics lc rgb '#e6e6e6'\n"
     << "set key top left\n"
     << "set title \"" << lab::gnuplot_text("many pyramids (10 rows, 55 boxes each), " + steps +
                                              " steps of 1/60 s, one thread, engines interleaved")
     << "\"\n"
     << "set xlabel 'dynamic bodies'\n"
     << "set ylabel 'CPU ms per step (median)'\n"
     << "plot for [i=2:" << contenders.size() + 1 << "] \"" << lab::gnuplot_text(csv_path.string())
     << "\" using 1:i with linespoints lw 2 pt 7 title columnheader(i)\n";
  const std::string png = (std::filesystem::path(directory) / "bench_scaling.png").string();
  lab::run_gnuplot(gp.str(), png);
  return png;
}

}  // namespace impulse2d::compare

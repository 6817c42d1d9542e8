/// @file compare_scale.cpp
#include "bench/compare/compare_scale.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace impulse2d::compare {
namespace {

// The scaling results, fewest bodies first.
std::vector<const SceneResult*> series(const std::vector<SceneResult>& results) {
  std::vector<const SceneResult*> points;
  for (const SceneResult& result : results) {
    if (result.scaling) points.push_back(&result);
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const SceneResult* a, const SceneResult* b) { return a->bodies < b->bodies; });
  return points;
}

double micros_per_body(const SceneResult& result, const Outcome& outcome) {
  return 1e3 * outcome.ms_per_step / static_cast<double>(std::max(1, result.bodies));
}

// The engine's per-body cost at the smallest size of the series it ran at (0 when none).
double smallest_cost(const std::vector<const SceneResult*>& points, std::size_t engine) {
  for (const SceneResult* point : points) {
    const Outcome& outcome = point->outcomes[engine];
    if (outcome.ran && outcome.ms_per_step > 0.0) return micros_per_body(*point, outcome);
  }
  return 0.0;
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// Bytes per body as text, "-" when not measured.
std::string per_body(double bytes, int bodies) {
  return bytes < 0.0 ? "-" : format("%.0f", bytes / static_cast<double>(std::max(1, bodies)));
}

// One row of cells per size and engine: bodies, steps, engine, ms/step, µs/body, ÷ smallest,
// heap B/body, resident B/body (the engine's name only, then "skipped", when left out).
std::vector<std::vector<std::string>> rows(const std::vector<Contender>& contenders,
                                           const std::vector<const SceneResult*>& points) {
  std::vector<std::vector<std::string>> table;
  for (const SceneResult* point : points) {
    for (std::size_t e = 0; e < contenders.size(); ++e) {
      const Outcome& outcome = point->outcomes[e];
      std::vector<std::string> row{std::to_string(point->bodies), std::to_string(point->steps),
                                   contenders[e].label};
      if (!outcome.ran) {
        row.insert(row.end(), {"skipped", "-", "-", "-", "-"});
      } else {
        const double cost = micros_per_body(*point, outcome);
        const double first = smallest_cost(points, e);
        row.insert(row.end(), {format("%.3f", outcome.ms_per_step), format("%.3f", cost),
                               first > 0.0 ? format("%.2f", cost / first) : "-",
                               per_body(outcome.memory.heap_bytes, point->bodies),
                               per_body(outcome.memory.resident_bytes, point->bodies)});
      }
      table.push_back(row);
    }
  }
  return table;
}

// Per engine: "label: a µs at N bodies -> b µs at M bodies, ratio".
std::vector<std::string> growth_lines(const std::vector<Contender>& contenders,
                                      const std::vector<const SceneResult*>& points) {
  std::vector<std::string> lines;
  for (std::size_t e = 0; e < contenders.size(); ++e) {
    const SceneResult* first = nullptr;
    const SceneResult* last = nullptr;
    for (const SceneResult* point : points) {
      const Outcome& outcome = point->outcomes[e];
      if (!outcome.ran || outcome.ms_per_step <= 0.0) continue;
      if (first == nullptr) first = point;
      last = point;
    }
    if (first == nullptr || last == first) continue;
    const double from = micros_per_body(*first, first->outcomes[e]);
    const double to = micros_per_body(*last, last->outcomes[e]);
    lines.push_back(contenders[e].label + ": " + format("%.3f", from) + " us/body at " +
                    std::to_string(first->bodies) + " bodies -> " + format("%.3f", to) +
                    " us/body at " + std::to_string(last->bodies) + ": " + format("%.2fx", to / from));
  }
  return lines;
}

const std::vector<std::string> headers{"bodies", "steps", "engine", "ms/step", "us/body",
                                       "/smallest", "heap B/body", "resident B/body"};

}  // namespace

void print_scale_summary(std::ostream& out, const std::vector<Contender>& contenders,
                         const std::vector<SceneResult>& results) {
  const std::vector<const SceneResult*> points = series(results);
  if (points.empty()) return;
  out << "\nscaling series per body: us/body = CPU microseconds per body per step (median step "
         "/ bodies); /smallest = that over the same engine's at the smallest size; heap and "
         "resident = bytes per body the engine's world holds after building and stepping\n";
  char line[256];
  auto print_row = [&](const std::vector<std::string>& cells) {
    std::snprintf(line, sizeof line, "%7s %5s %-26s %9s %8s %9s %11s %15s\n", cells[0].c_str(),
                  cells[1].c_str(), cells[2].c_str(), cells[3].c_str(), cells[4].c_str(),
                  cells[5].c_str(), cells[6].c_str(), cells[7].c_str());
    out << line;
  };
  print_row(headers);
  for (const std::vector<std::string>& row : rows(contenders, points)) print_row(row);
  out << "per-body cost, largest size over smallest:\n";
  for (const std::string& growth : growth_lines(contenders, points)) out << "  " << growth << "\n";
}

void write_scale_files(const std::string& directory, const std::vector<Contender>& contenders,
                       const std::vector<SceneResult>& results, const std::string& machine) {
  const std::vector<const SceneResult*> points = series(results);
  if (points.empty()) return;
  const std::filesystem::path out(directory);
  std::ofstream csv(out / "scale.csv", std::ios::binary | std::ios::trunc);
  csv << "scene,bodies,steps,engine,ms_per_step,us_per_body,cost_vs_smallest,heap_bytes_per_body,"
         "resident_bytes_per_body\n";
  std::size_t index = 0;
  const std::vector<std::vector<std::string>> table = rows(contenders, points);
  for (const SceneResult* point : points) {
    for (std::size_t e = 0; e < contenders.size(); ++e, ++index) {
      if (!point->outcomes[e].ran) continue;
      const std::vector<std::string>& row = table[index];
      csv << point->name << "," << row[0] << "," << row[1] << "," << row[2];
      for (std::size_t c = 3; c < row.size(); ++c) csv << "," << (row[c] == "-" ? "" : row[c]);
      csv << "\n";
    }
  }
  std::ofstream markdown(out / "scale.md", std::ios::binary | std::ios::trunc);
  markdown << "Scaling series per body (`bench_compare`), " << machine << ".\n\n"
           << "| bodies | steps | engine | ms/step | µs/body/step | ÷ smallest | heap B/body | resident B/body |\n"
           << "|---:|---:|---|---:|---:|---:|---:|---:|\n";
  for (const std::vector<std::string>& row : table) {
    markdown << "|";
    for (const std::string& cell : row) markdown << " " << cell << " |";
    markdown << "\n";
  }
  markdown << "\nPer-body cost, largest size over smallest:\n\n";
  for (const std::string& growth : growth_lines(contenders, points)) markdown << "- " << growth << "\n";
  if (!csv || !markdown) throw std::runtime_error("cannot write scale.csv / scale.md into " + directory);
}

}  // namespace impulse2d::compare

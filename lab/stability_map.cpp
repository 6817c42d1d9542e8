/// @file stability_map.cpp
#include "lab/stability_map.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "lab/engine_simulation.h"
#include "lab/gnuplot.h"
#include "lab/lab_peers.h"
#include "lab/lab_result.h"
#include "lab/lab_sweep.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "image/png.h"
#include "scene/interrupt.h"

namespace impulse2d::lab {
namespace {

std::string value_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

LabMethod with_value(const Stressor& stressor, double value, LabMethod method) {
  if (stressor.sets_time_step) method.time_step = static_cast<float>(value / 1000.0);
  return method;
}

double between(const Stressor& stressor, double pass, double fail) {
  if (stressor.integer) return std::floor((pass + fail) / 2.0);
  if (pass > 0.0 && fail > 0.0) return std::sqrt(pass * fail);
  return (pass + fail) / 2.0;
}

}  // namespace

std::vector<LabMethod> stability_methods(bool quick) {
  std::vector<LabMethod> methods;
  const auto add = [&](LabMethod method, auto change) {
    change(method);
    methods.push_back(method);
  };
  const LabMethod standard;  // the default: the soft step, 4 sub-steps of 1 pass
  const LabMethod accumulated = method_for(SolverMethod::Accumulated);  // 1 x 16
  // The tutorial's solver at its 10 iterations and linear projection, one step a frame.
  add(method_for(SolverMethod::PerIteration), [](LabMethod& m) {
    m.velocity_iterations = 10;
    m.position_correction = PositionCorrection::LinearProjection;
  });
  add(standard, [](LabMethod&) {});
  add(accumulated, [](LabMethod&) {});
  if (!quick) {
    add(accumulated, [](LabMethod& m) { m.warm_starting = false; });
    add(accumulated, [](LabMethod& m) { m.position_correction = PositionCorrection::LinearProjection; });
    add(accumulated, [](LabMethod& m) {
      m.substeps = 4;
      m.velocity_iterations = 2;
    });
    add(accumulated, [](LabMethod& m) { m.integrator = Integrator::ExplicitEuler; });
    add(standard, [](LabMethod& m) { m.warm_starting = false; });
  }
  add(standard, [](LabMethod& m) { m.continuous = false; });
  add(standard, [](LabMethod& m) {
    m.continuous = false;
    m.speculative_margin = 0.0f;
  });
  for (const LabMethod& peer : peer_methods(1.0f / 60.0f)) {
    if (engine_available(peer.engine)) methods.push_back(peer);
  }
  return methods;
}

bool stress_passes(const Stressor& stressor, double value, const LabMethod& method,
                   std::string* reason) {
  const LabMethod run_method = with_value(stressor, value, method);
  for (const LabScenario& scenario : stressor.scenarios(value)) {
    std::unique_ptr<LabSimulation> simulation = make_simulation(scenario.scene, run_method);
    const RunMeasurement run = run_scenario(scenario, *simulation, true, false);
    const bool diverged = run.diverged || !std::isfinite(run.error);
    if (diverged || run.error > scenario.metric.threshold) {
      if (reason) {
        *reason = diverged ? "diverged"
                           : "error " + value_text(run.error) + " " + scenario.metric.unit + " > " +
                                 value_text(scenario.metric.threshold) + " " + scenario.metric.unit;
      }
      return false;
    }
  }
  return true;
}

std::vector<StabilityCell> run_stability_map(const std::vector<Stressor>& stressors,
                                             const std::vector<LabMethod>& methods, int bisections,
                                             const std::function<void(int, int)>& progress) {
  std::vector<StabilityCell> cells;
  const int total = static_cast<int>(stressors.size() * methods.size());
  for (const LabMethod& method : methods) {
    for (const Stressor& stressor : stressors) {
      StabilityCell cell;
      cell.method = method;
      cell.stressor = stressor.name;
      cell.unit = stressor.unit;
      std::size_t passed = 0;
      std::string reason;
      for (; passed < stressor.ladder.size(); ++passed) {
        demos::check_interrupt();
        ++cell.runs;
        if (!stress_passes(stressor, stressor.ladder[passed], method, &reason)) break;
      }
      cell.any_pass = passed > 0;
      cell.all_pass = passed == stressor.ladder.size();
      cell.level = static_cast<double>(passed) / static_cast<double>(stressor.ladder.size());
      if (!cell.all_pass) {
        cell.first_fail = stressor.ladder[passed];
        cell.fail_reason = reason;
      }
      if (cell.any_pass) cell.last_pass = stressor.ladder[passed - 1];
      if (cell.any_pass && !cell.all_pass) {
        for (int i = 0; i < bisections; ++i) {
          const double middle = between(stressor, cell.last_pass, cell.first_fail);
          if (middle == cell.last_pass || middle == cell.first_fail) break;
          demos::check_interrupt();
          ++cell.runs;
          std::string middle_reason;
          if (stress_passes(stressor, middle, method, &middle_reason)) {
            cell.last_pass = middle;
          } else {
            cell.first_fail = middle;
            cell.fail_reason = middle_reason;
          }
        }
      }
      cells.push_back(cell);
      if (progress) progress(static_cast<int>(cells.size()), total);
    }
  }
  return cells;
}

std::string stability_csv(const std::vector<StabilityCell>& cells) {
  std::string text =
      "method,engine,stressor,unit,passes_easiest,passes_all,last_pass,first_fail,level,runs,"
      "fail_reason\n";
  for (const StabilityCell& cell : cells) {
    text += method_label(cell.method) + "," + engine_name(cell.method.engine) + "," + cell.stressor +
            "," + cell.unit + "," + (cell.any_pass ? "1" : "0") + "," + (cell.all_pass ? "1" : "0") +
            "," + (cell.any_pass ? value_text(cell.last_pass) : "") + "," +
            (cell.all_pass ? "" : value_text(cell.first_fail)) + "," + value_text(cell.level) + "," +
            std::to_string(cell.runs) + ",\"" + cell.fail_reason + "\"\n";
  }
  return text;
}

void draw_stability_heat_map(const std::vector<StabilityCell>& cells,
                             const std::vector<Stressor>& stressors, const std::string& png_path) {
  std::vector<std::string> rows;
  for (const StabilityCell& cell : cells) {
    const std::string label = method_label(cell.method);
    if (std::find(rows.begin(), rows.end(), label) == rows.end()) rows.push_back(label);
  }
  const int width = 220 + 150 * static_cast<int>(stressors.size());
  const int height = 170 + 42 * static_cast<int>(rows.size());
  std::ostringstream gp;
  gp << "set terminal pngcairo size " << width << "," << height << " font 'DejaVu Sans,9' noenhanced\n"
     << "set output OUTPUT\n"
     << "set lmargin at screen " << 200.0 / width << "\nset rmargin at screen " << 1.0 - 120.0 / width
     << "\nset bmargin at screen " << 20.0 / height << "\nset tmargin at screen "
     << 1.0 - 130.0 / height << "\n"
     << "set title \"Stability map: how far each method gets along each stressor before it "
        "fails (value = hardest passed; 'x' = fails the easiest; '>= v' or '<= v' = passes all)\" offset 0,4\n"
     << "set palette defined (0 '#D55E00', 0.5 '#F0E442', 1 '#009E73')\nset cbrange [0:1]\n"
     << "set cblabel 'share of the ladder passed'\n"
     << "set xrange [-0.5:" << stressors.size() - 0.5 << "]\nset yrange [" << rows.size() - 0.5
     << ":-0.5]\n"
     << "set x2tics (";
  for (std::size_t i = 0; i < stressors.size(); ++i) {
    gp << (i ? ", " : "") << "\"" << gnuplot_text(stressors[i].name) << "\\n("
       << gnuplot_text(stressors[i].unit) << ")\" " << i;
  }
  gp << ")\nunset xtics\nset x2tics scale 0\nset ytics (";
  for (std::size_t i = 0; i < rows.size(); ++i) gp << (i ? ", " : "") << "\"" << gnuplot_text(rows[i]) << "\" " << i;
  gp << ") scale 0\n";
  gp << "$cells << EOD\n";
  std::vector<std::string> labels;
  for (const StabilityCell& cell : cells) {
    const auto row = std::find(rows.begin(), rows.end(), method_label(cell.method)) - rows.begin();
    std::size_t column = 0;
    while (column < stressors.size() && stressors[column].name != cell.stressor) ++column;
    gp << column << " " << row << " " << cell.level << "\n";
    // Ladders run from easy to hard; a descending one (the friction angle) is passed "down to".
    const bool descending = stressors[column].ladder.front() > stressors[column].ladder.back();
    const std::string text = !cell.any_pass ? "x"
                             : cell.all_pass ? (descending ? "<= " : ">= ") + value_text(cell.last_pass)
                                             : value_text(cell.last_pass);
    labels.push_back("set label \"" + gnuplot_text(text) + "\" at " + std::to_string(column) + "," +
                     std::to_string(row) + " center front font ',10'");
  }
  gp << "EOD\n";
  for (const std::string& label : labels) gp << label << "\n";
  gp << "plot $cells using 1:2:3 with image notitle\n";
  run_gnuplot(gp.str(), png_path);
}

void draw_boundary_sheet(const Stressor& stressor, const StabilityCell& cell,
                         const std::string& png_path) {
  constexpr int tile_width = 480, tile_height = 360, gap = 8;
  render::FrameRenderer renderer(tile_width, tile_height);
  render::Frame sheet;
  sheet.width = 2 * tile_width + gap;
  sheet.height = tile_height;
  sheet.rgba.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 255);
  const double values[2] = {cell.last_pass, cell.first_fail};
  for (int side = 0; side < 2; ++side) {
    const LabScenario scenario = stressor.scenarios(values[side]).front();
    const LabMethod method = with_value(stressor, values[side], cell.method);
    EngineSimulation simulation(scenario.scene, method);
    const render::Camera camera =
        render::Camera::fit(render::world_bounds(simulation.world()), tile_width, tile_height);
    const auto steps = static_cast<std::int64_t>(std::ceil(scenario.duration / method.time_step - 1e-6));
    for (std::int64_t step = 0; step < steps; ++step) simulation.step();
    render::FrameOptions options;
    options.show_legend = false;
    render::HudInfo hud;
    hud.scene_name = stressor.name + " " + value_text(values[side]) + " " + stressor.unit + ", " +
                     method_label(cell.method) + ": " + (side == 0 ? "passes" : "fails");
    hud.step = steps;
    const render::Frame frame = renderer.render(simulation.world(), camera, options, hud);
    for (int y = 0; y < tile_height; ++y) {
      std::copy_n(frame.rgba.begin() + static_cast<std::ptrdiff_t>(y) * tile_width * 4, tile_width * 4,
                  sheet.rgba.begin() + (static_cast<std::ptrdiff_t>(y) * sheet.width +
                                        side * (tile_width + gap)) * 4);
    }
  }
  image::save_png(png_path, sheet);
}

}  // namespace impulse2d::lab

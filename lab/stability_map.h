#pragma once
/// @file stability_map.h
/// Where methods fail: each method is pushed along each stressor's ladder until it breaks; the
/// boundary is then narrowed by bisection. Written as a CSV, a heat map (method x stressor ->
/// threshold) and contact sheets of the passing and failing side of a few boundaries.

#include <functional>
#include <string>
#include <vector>

#include "lab/lab_method.h"
#include "lab/stressors.h"

namespace impulse2d::lab {

/// The boundary of one method on one stressor.
struct StabilityCell {
  LabMethod method;          ///< the method
  std::string stressor;      ///< stressor name
  std::string unit;          ///< of the values
  bool any_pass = false;     ///< the easiest value passed
  bool all_pass = false;     ///< every value of the ladder passed
  double last_pass = 0.0;    ///< the hardest value passed before the first failure
  double first_fail = 0.0;   ///< the easiest value that failed (after bisection)
  double level = 0.0;        ///< 0..1: how far up the ladder the method got (for the heat map)
  std::string fail_reason;   ///< the failing run's error, e.g. "error 3.2 m > 0.11 m"
  int runs = 0;              ///< runs spent on this cell
};

/// The methods of the map's rows (peers included when compiled in).
std::vector<LabMethod> stability_methods(bool quick);

/// True when `method` passes every scenario of `stressor` at `value`; `reason` gets the first
/// failing run's explanation.
bool stress_passes(const Stressor& stressor, double value, const LabMethod& method,
                   std::string* reason);

/// Finds every cell's boundary (`bisections` halvings between the last pass and first fail).
/// `progress` (may be empty) is called with (cells done, cells in total). Throws
/// `demos::Interrupted` when SIGINT, SIGTERM or SIGHUP arrives.
std::vector<StabilityCell> run_stability_map(const std::vector<Stressor>& stressors,
                                             const std::vector<LabMethod>& methods, int bisections,
                                             const std::function<void(int, int)>& progress);

/// The map as CSV text.
std::string stability_csv(const std::vector<StabilityCell>& cells);

/// Draws the heat map PNG with gnuplot.
void draw_stability_heat_map(const std::vector<StabilityCell>& cells,
                             const std::vector<Stressor>& stressors, const std::string& png_path);

/// For one cell with both a passing and a failing value: a PNG with the final frame of the run
/// at the last passing value (left) and at the first failing value (right).
void draw_boundary_sheet(const Stressor& stressor, const StabilityCell& cell,
                         const std::string& png_path);

}  // namespace impulse2d::lab

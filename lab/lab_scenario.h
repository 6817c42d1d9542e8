#pragma once
/// @file lab_scenario.h
/// A lab scenario: a scene file with an exact answer. Each is one JSON file (lab/scenarios/
/// by default, so users can add their own):
///
///     {"description": "...", "answer": "y = y0 + v0 t - g t^2 / 2", "duration": 2,
///      "metric": {"kind": "free_flight", "body": "ball", "unit": "m", "threshold": 0.05,
///                 "meaning": "largest distance from the exact trajectory"},
///      "scene": { ...a scene file, as `impulse2d render` reads... }}
///
/// Metric fields by kind: `body` (free_flight, slope_motion, bounce_apexes, tunnel,
/// surface_ride), `surface` (slope_motion, surface_ride, tunnel: the wall), `rolls`
/// (slope_motion, surface_ride), `measure` (surface_ride: normal_speed, angular_speed or
/// acceleration), `ground`, `apexes`, `rest_height` (bounce_apexes),
/// `bodies` (collision_1d: two; cradle: the row in order; rest: optional, default every dynamic
/// body); `joint` (pendulum_period, spring_frequency, rope_slack), `joints` (joint_drift:
/// optional, default every revolute, weld and rigid distance joint), `after` (joint_drift,
/// surface_ride's speeds: seconds before errors count). Bodies and joints are
/// named by their `name` in the scene; a body named there stands for its creation index, in
/// which a chain counts one body per link (a chain named as `surface` is its first link).

#include <string>
#include <vector>

#include "lab/lab_metric.h"
#include "scene/scene.h"

namespace impulse2d::lab {

/// One scenario of the lab.
struct LabScenario {
  std::string name;         ///< the file's stem, e.g. "projectile"
  std::string description;  ///< one line
  std::string answer;       ///< the exact answer, as a formula
  double duration = 0.0;    ///< simulated seconds per run
  MetricSpec metric;        ///< error metric, unit, pass threshold
  demos::Scene scene;       ///< the scene as the JSON scene loader reads it
  std::string source;       ///< path of the file
};

/// Reads and validates a scenario file (a regular file of at most 4 MiB: a FIFO or a device is
/// refused, not read). Throws `demos::UsageError` "<file>: <json path>: <reason>" for anything
/// wrong, including a metric naming a body the scene does not have.
LabScenario load_lab_scenario(const std::string& path);

/// As `load_lab_scenario`, from text already read; `file` names it in messages and gives the
/// scenario's name (its stem).
LabScenario parse_lab_scenario(const std::string& text, const std::string& file);

/// Every `*.json` scenario in `directory`, sorted by file name. Throws `demos::UsageError` when
/// the directory cannot be read or has no scenario.
std::vector<LabScenario> load_lab_scenarios(const std::string& directory);

/// The lab's data (scenarios/, tuned/): installed, `share/impulse2d/lab` beside the program's
/// `bin/` (found through /proc/self/exe), else the source tree the program was built from.
/// Throws `std::runtime_error` naming both places when neither holds a scenarios/ folder.
std::string lab_data_directory();

/// The scenarios shipped with impulse2d: `lab_data_directory()`'s scenarios/.
std::string default_scenario_directory();

}  // namespace impulse2d::lab

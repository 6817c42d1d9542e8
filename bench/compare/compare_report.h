#pragma once
/// @file compare_report.h
/// bench_compare's outputs: the table printed per scene, the ratios ours/theirs, and the same
/// figures as CSV and as a Markdown table (for the README).

#include <ostream>
#include <string>
#include <vector>

#include "bench/compare/compare_run.h"

namespace impulse2d::compare {

/// One scene's results, one outcome per contender (in `contenders` order).
struct SceneResult {
  std::string name;               ///< the scene's name
  std::string description;        ///< one line
  Judge judge = Judge::Pyramids;  ///< which stability figures apply
  int bodies = 0;                 ///< dynamic bodies
  int steps = 0;                  ///< steps run
  bool scaling = false;           ///< part of the scaling series
  std::vector<Outcome> outcomes;  ///< per contender
  double seconds = 0.0;           ///< wall-clock time of the whole scene (every engine), s
};

/// The table of one scene: per engine ms/step, its ratio to each peer, and the stability
/// figures that apply ("-" for the others).
void print_scene_table(std::ostream& out, const std::vector<Contender>& contenders,
                       const SceneResult& result);

/// Every impulse2d contender's ms/step divided by every peer's, per scene (below 1: ours is
/// faster).
void print_ratios(std::ostream& out, const std::vector<Contender>& contenders,
                  const std::vector<SceneResult>& results);

/// One line per scene and engine: scene,bodies,steps,engine,ms_per_step,sag_m,side_m,moved,
/// depth_m,out,non_finite.
void write_csv(std::ostream& out, const std::vector<Contender>& contenders,
               const std::vector<SceneResult>& results);

/// A Markdown table: one row per scene and engine with ms/step, the ratios to the peers and the
/// stability figures.
void write_markdown(std::ostream& out, const std::vector<Contender>& contenders,
                    const std::vector<SceneResult>& results);

}  // namespace impulse2d::compare

#pragma once
/// @file stability.h
/// The stability figures printed beside every speed, so that speed is never bought with
/// collapse. They are read from the bodies' states alone, so every engine is judged alike.

#include <vector>

#include "bench/compare/compare_scene.h"
#include "lab/lab_simulation.h"

namespace impulse2d::compare {

/// What a run left standing.
struct Stability {
  float sag = 0.0f;   ///< Pyramids: largest drop of a pyramid's top box below where built, m
  float side = 0.0f;  ///< Pyramids: largest sideways move of any box, m
  int moved = 0;      ///< Pyramids: boxes moved sideways more than 0.1 m or turned over 5 degrees
  /// Deepest overlap of any two bodies, m, the largest of the samples taken during the run
  /// (sharp-cornered shapes: Box2D's corners are rounded by 1 cm, so its corner contacts can
  /// read up to ~4 mm deeper than they are).
  float depth = 0.0f;
  /// Pit: balls outside the box at the end. Rain: bodies recycled during the run.
  int out = 0;
  int non_finite = 0;  ///< bodies whose state is not finite at the end (a blow-up)
};

/// Fills `sag`, `side`, `moved`, `non_finite` and (Pit) `out` from the final `states` (creation
/// order) of a run of `scene`.
void judge_final_states(const CompareScene& scene, const std::vector<lab::BodyState>& states,
                        Stability& stability);

/// The deepest overlap between any two bodies of `scene` (not both static) placed as `states`
/// say, m (0 when nothing overlaps): sort-and-sweep on bounds, then the narrow phase.
float deepest_overlap(const CompareScene& scene, const std::vector<lab::BodyState>& states);

}  // namespace impulse2d::compare

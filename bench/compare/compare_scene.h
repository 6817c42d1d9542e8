#pragma once
/// @file compare_scene.h
/// The scenes of bench_compare, built once as a list of bodies that every engine copies: the
/// 20-row and 100-row pyramids and the many pyramids of Box2D v3's benchmark, a ball pit, rain,
/// and the scaling series (many pyramids of 1k to 100k boxes). Gravity -10 m/s^2, 1/60 s.

#include <string>
#include <vector>

#include "core/body.h"
#include "core/shape.h"

namespace impulse2d::compare {

/// One body of a scene, as `World::create_body` takes it.
struct BodySpec {
  BodyDef def;  ///< pose, velocity, material, type
  Shape shape;  ///< in body coordinates
};

/// Which stability figures a scene is judged by.
enum class Judge {
  Pyramids,  ///< boxes must stay where they were built: top sag, sideways drift, turn
  Pit,       ///< balls must stay inside the box (`CompareScene::container`)
  Rain,      ///< bodies that fall off the field are recycled (`CompareScene::recycle`)
};

/// How rain recycles a body that fell out: it is put back above the field at the next of
/// `slots` places (used in turn) that has been free for `spacing_steps` steps, so it never
/// lands inside the body put there before; with no place free it waits, falling.
struct Recycle {
  float below = 0.0f;     ///< a dynamic body whose centre is below this height is recycled, m
  float left = 0.0f;      ///< x of the first place, m
  float right = 0.0f;     ///< x of the last place, m
  float top = 0.0f;       ///< height of the places, m
  float speed = 0.0f;     ///< downward speed of a recycled body, m/s
  int slots = 1;          ///< places along the line
  int spacing_steps = 1;  ///< steps before a place is used again
};

/// A scene of the benchmark.
struct CompareScene {
  std::string name;               ///< e.g. "large_pyramid"
  std::string description;        ///< one line: what it is
  std::vector<BodySpec> bodies;   ///< in creation order
  int dynamic_count = 0;          ///< bodies that move (the count charted)
  int steps = 0;                  ///< steps of a full run
  Judge judge = Judge::Pyramids;  ///< which stability figures apply
  std::vector<int> tops;          ///< Pyramids: creation index of each pyramid's top box
  Aabb container;                 ///< Pit: the inside of the box, m
  Recycle recycle;                ///< Rain: where fallen bodies go
  bool scaling = false;           ///< part of the scaling series (charted against body count)
};

/// Box2D v3's `large_pyramid`: a static ground box of half-size (100, 1) at (0, -1) and `rows`
/// rows of boxes of half-size 0.5, touching, 1 m apart, density 1, friction 0.6.
CompareScene pyramid_scene(const std::string& name, int rows, int steps);

/// Box2D v3's `many_pyramids`: `count` pyramids of `rows` rows (boxes of half-size 0.5), laid
/// `columns` to a row of pyramids, each row of pyramids on its own ground 2 (rows + 1) * 0.5 m
/// above the last (v3's ground segments are thin static boxes here, 0.2 m thick).
CompareScene many_pyramids_scene(const std::string& name, int count, int columns, int rows,
                                 int steps);

/// One size of the scaling series: how many pyramids of 55 boxes, and so how many bodies.
struct ScalingSize {
  int pyramids = 0;  ///< pyramids of 10 rows
  int bodies = 0;    ///< dynamic bodies, 55 per pyramid
};

/// The scaling series, fewest bodies first (bench_compare and bench_v3 share it): 18, 36, 91,
/// 182, 364, 910 and 1820 pyramids, that is 990, 1980, 5005, 10010, 20020, 50050 and 100100
/// bodies (the largest 91 rows of pyramids, 1 km high).
const std::vector<ScalingSize>& scaling_sizes();

/// The scaling scene of `pyramids` pyramids: `many_pyramids_scene("scaling_<bodies>",
/// pyramids, 20, 10, steps)` marked `scaling`.
CompareScene scaling_scene(int pyramids, int steps);

/// `balls` circles of radius 0.25 m (density 1, friction 0.6, no bounce) dropped in rows of
/// `columns` into an open box just wider than a row.
CompareScene ball_pit_scene(const std::string& name, int balls, int columns, int steps);

/// `count` bodies (boxes of half-size 0.25 and circles of radius 0.25 in turn) raining from a
/// grid 60 m wide onto a 40 m field with no walls; those that fall 20 m below it are recycled.
CompareScene rain_scene(const std::string& name, int count, int steps);

}  // namespace impulse2d::compare

#pragma once
/// @file speculative_meeting.h
/// Whether two bodies really meet within the coming step: the test that keeps speculative
/// contacts from acting on pairs that only pass each other.
///
/// A speculative point with gap g > 0 and relative normal velocity vn < 0 lets the solver stop
/// the approach once -vn h > g: it assumes the normal stays fixed while the gap closes. When
/// the surfaces slide past each other (two discs in parallel lanes, a box passing a corner)
/// the normal turns away before the gap closes, and that assumption makes a "ghost" impulse
/// between bodies that never touch. The cure is to ask the geometry: move both shapes along
/// their predicted velocities over the step and find their smallest distance. The distance
/// between two convex shapes translating at constant velocities is a convex function of time
/// (the distance from the origin to their moving Minkowski difference), so a golden-section
/// search finds its minimum without missing a dip. Rotation within the step is not swept:
/// each rotating body's shape is grown by the distance its farthest point turns through
/// (|w| r h), which can only make a meeting more likely.

#include "core/solver/body_shapes.h"
#include "core/contact.h"
#include "core/settings.h"

namespace impulse2d {

/// The motion of a body over the coming step as the meeting test sees it.
struct PredictedMotion {
  vec2 velocity{0.0f, 0.0f};  ///< m/s: velocity after this step's gravity and forces
  float turn_reach = 0.0f;    ///< metres the farthest surface point turns through in the step
};

/// The motion `body` is predicted to make over a step of `h` seconds before contacts act:
/// its velocity with gravity and applied forces added (dynamic), as it is (kinematic), or none
/// (static, asleep).
PredictedMotion predict_motion(const Body& body, const WorldSettings& settings, float h);

/// Smallest distance (metres, 0 when they overlap) between `shape_a` at `transform_a` and
/// `shape_b` at `transform_b` while they translate at `motion_a.velocity` and
/// `motion_b.velocity` for `h` seconds; the search stops as soon as it finds a distance at or
/// below `enough` (metres), which it then returns.
float closest_approach(const Shape& shape_a, const Transform& transform_a,
                       const PredictedMotion& motion_a, const Shape& shape_b,
                       const Transform& transform_b, const PredictedMotion& motion_b, float h,
                       float enough = 0.0f);

/// True when `contact` is a ghost: every point is apart (depth < 0), the linearised constraint
/// would stop at least one point within `h` seconds (its gap closes at the predicted normal
/// speed), and yet the shapes, moved along their predicted motion, stay apart by more than the
/// turn reaches for the whole step. Such a contact gets no impulse; a contact whose points do
/// not close within the step is kept (it only acts if the solve drives its bodies together).
bool is_ghost_contact(const Body& a, const PredictedMotion& motion_a, const Body& b,
                      const PredictedMotion& motion_b, const Contact& contact, float h);

}  // namespace impulse2d

#pragma once
/// @file joint_helpers.h
/// Joints for the built-in scene builders, with anchors given as world points (as scene files
/// write them) at the bodies' current poses.

#include "core/joint.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// A hinge between `a` and `b` at the world point `anchor` (metres), keeping their current
/// relative angle as joint angle 0. With `lower` < `upper` the joint angle is limited.
JointId add_hinge(World& world, BodyId a, BodyId b, vec2 anchor, float lower = 0.0f, float upper = 0.0f);

/// `world_point` in the frame of `body` (metres from its centre of mass).
vec2 local_point(const World& world, BodyId body, vec2 world_point);

}  // namespace impulse2d::demos

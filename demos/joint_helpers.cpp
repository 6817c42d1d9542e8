/// @file joint_helpers.cpp
#include "demos/joint_helpers.h"

#include "core/world.h"

namespace impulse2d::demos {

vec2 local_point(const World& world, BodyId body, vec2 world_point) {
  return world.body(body).transform.apply_inverse(world_point);
}

JointId add_hinge(World& world, BodyId a, BodyId b, vec2 anchor, float lower, float upper) {
  RevoluteJointDef def;
  def.body_a = a;
  def.body_b = b;
  def.local_anchor_a = local_point(world, a, anchor);
  def.local_anchor_b = local_point(world, b, anchor);
  def.reference_angle = world.body(b).angle - world.body(a).angle;
  if (lower < upper) {
    def.enable_limit = true;
    def.lower_angle = lower;
    def.upper_angle = upper;
  }
  return world.create_joint(def);
}

}  // namespace impulse2d::demos

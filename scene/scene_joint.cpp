/// @file scene_joint.cpp
#include "scene/scene_joint.h"

#include "core/world.h"

#include <algorithm>

namespace impulse2d::demos {

const char* joint_type_name(JointType type) {
  switch (type) {
    case JointType::Revolute: return "revolute";
    case JointType::Prismatic: return "prismatic";
    case JointType::Distance: return "distance";
    case JointType::Weld: return "weld";
    case JointType::Wheel: return "wheel";
    case JointType::Motor: return "motor";
    case JointType::Mouse: return "mouse";
  }
  return "?";
}

namespace {

vec2 unit_or_zero(vec2 v) {
  const float length = glm::length(v);
  return length > 0.0f ? v / length : vec2(0.0f, 0.0f);
}

// The scene's world anchors, axis and current relative angle in the bodies' frames.
struct Placement {
  vec2 local_a;          // A's anchor, A's frame
  vec2 local_b;          // B's anchor, B's frame
  vec2 local_axis;       // unit axis, A's frame
  float relative_angle;  // B's angle minus A's, radians
};

template <class Def>
void set_anchors(Def& def, const Placement& placement) {
  def.local_anchor_a = placement.local_a;
  def.local_anchor_b = placement.local_b;
}

// Creates `def` between `a` and `b` with the spec's collide_connected.
template <class Def>
JointId create(World& world, Def def, BodyId a, BodyId b, const JointSpec& spec) {
  def.body_a = a;
  def.body_b = b;
  def.collide_connected = spec.collide_connected;
  return world.create_joint(def);
}

}  // namespace

JointId create_scene_joint(World& world, const JointSpec& spec, BodyId a, BodyId b) {
  const BodyView body_a = world.body(a);
  const BodyView body_b = world.body(b);
  const Placement placement{body_a.transform.apply_inverse(spec.anchor_a),
                            body_b.transform.apply_inverse(spec.anchor_b),
                            body_a.transform.rotation.inverse_rotate(unit_or_zero(spec.axis)),
                            body_b.angle - body_a.angle};
  switch (spec.type) {
    case JointType::Revolute: {
      RevoluteJointDef def = spec.revolute;
      set_anchors(def, placement);
      def.reference_angle = placement.relative_angle;
      return create(world, def, a, b, spec);
    }
    case JointType::Prismatic: {
      PrismaticJointDef def = spec.prismatic;
      set_anchors(def, placement);
      def.local_axis_a = placement.local_axis;
      def.reference_angle = placement.relative_angle;
      return create(world, def, a, b, spec);
    }
    case JointType::Distance: {
      DistanceJointDef def = spec.distance;
      set_anchors(def, placement);
      if (!spec.has_length) def.length = std::max(glm::length(spec.anchor_b - spec.anchor_a), 0.005f);
      return create(world, def, a, b, spec);
    }
    case JointType::Weld: {
      WeldJointDef def = spec.weld;
      set_anchors(def, placement);
      def.reference_angle = placement.relative_angle;
      return create(world, def, a, b, spec);
    }
    case JointType::Wheel: {
      WheelJointDef def = spec.wheel;
      set_anchors(def, placement);
      def.local_axis_a = placement.local_axis;
      return create(world, def, a, b, spec);
    }
    case JointType::Motor: return create(world, spec.motor, a, b, spec);
    case JointType::Mouse: {
      MouseJointDef def = spec.mouse;
      def.local_anchor_b = spec.anchor_b_is_center ? vec2(0.0f, 0.0f) : placement.local_b;
      return create(world, def, a, b, spec);
    }
  }
  return JointId{};
}

}  // namespace impulse2d::demos

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

}  // namespace

JointId create_scene_joint(World& world, const JointSpec& spec, BodyId a, BodyId b) {
  const BodyView body_a = world.body(a);
  const BodyView body_b = world.body(b);
  const vec2 local_a = body_a.transform.apply_inverse(spec.anchor_a);
  const vec2 local_b = body_b.transform.apply_inverse(spec.anchor_b);
  const vec2 local_axis = body_a.transform.rotation.inverse_rotate(unit_or_zero(spec.axis));
  const float relative_angle = body_b.angle - body_a.angle;
  switch (spec.type) {
    case JointType::Revolute: {
      RevoluteJointDef def = spec.revolute;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_a = local_a;
      def.local_anchor_b = local_b;
      def.reference_angle = relative_angle;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Prismatic: {
      PrismaticJointDef def = spec.prismatic;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_a = local_a;
      def.local_anchor_b = local_b;
      def.local_axis_a = local_axis;
      def.reference_angle = relative_angle;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Distance: {
      DistanceJointDef def = spec.distance;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_a = local_a;
      def.local_anchor_b = local_b;
      if (!spec.has_length) def.length = std::max(glm::length(spec.anchor_b - spec.anchor_a), 0.005f);
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Weld: {
      WeldJointDef def = spec.weld;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_a = local_a;
      def.local_anchor_b = local_b;
      def.reference_angle = relative_angle;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Wheel: {
      WheelJointDef def = spec.wheel;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_a = local_a;
      def.local_anchor_b = local_b;
      def.local_axis_a = local_axis;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Motor: {
      MotorJointDef def = spec.motor;
      def.body_a = a;
      def.body_b = b;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
    case JointType::Mouse: {
      MouseJointDef def = spec.mouse;
      def.body_a = a;
      def.body_b = b;
      def.local_anchor_b = spec.anchor_b_is_center ? vec2(0.0f, 0.0f) : local_b;
      def.collide_connected = spec.collide_connected;
      return world.create_joint(def);
    }
  }
  return JointId{};
}

}  // namespace impulse2d::demos

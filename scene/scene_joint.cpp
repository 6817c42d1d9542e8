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

// Creates `def` between `a` and `b`.
template <class Def>
JointId create(World& world, Def def, BodyId a, BodyId b) {
  def.body_a = a;
  def.body_b = b;
  return world.create_joint(def);
}

}  // namespace

JointSpec complete_joint_spec(const JointSpec& spec, const BodyView& a, const BodyView& b) {
  JointSpec done = spec;
  const vec2 local_a = a.transform.apply_inverse(spec.anchor_a);
  const vec2 local_b = b.transform.apply_inverse(spec.anchor_b);
  const vec2 local_axis = a.transform.rotation.inverse_rotate(unit_or_zero(spec.axis));
  const float relative_angle = b.angle - a.angle;
  const auto anchors = [&](auto& def) {
    def.local_anchor_a = local_a;
    def.local_anchor_b = local_b;
  };
  anchors(done.revolute);
  anchors(done.prismatic);
  anchors(done.distance);
  anchors(done.weld);
  anchors(done.wheel);
  done.mouse.local_anchor_b = spec.anchor_b_is_center ? vec2(0.0f, 0.0f) : local_b;
  done.prismatic.local_axis_a = done.wheel.local_axis_a = local_axis;
  done.revolute.reference_angle = done.prismatic.reference_angle = done.weld.reference_angle =
      relative_angle;
  if (!spec.has_length) {
    done.distance.length = std::max(glm::length(spec.anchor_b - spec.anchor_a), 0.005f);
  }
  done.revolute.collide_connected = done.prismatic.collide_connected =
      done.distance.collide_connected = done.weld.collide_connected =
          done.wheel.collide_connected = done.motor.collide_connected =
              done.mouse.collide_connected = spec.collide_connected;
  return done;
}

JointId create_scene_joint(World& world, const JointSpec& spec, BodyId a, BodyId b) {
  const JointSpec done = complete_joint_spec(spec, world.body(a), world.body(b));
  switch (spec.type) {
    case JointType::Revolute: return create(world, done.revolute, a, b);
    case JointType::Prismatic: return create(world, done.prismatic, a, b);
    case JointType::Distance: return create(world, done.distance, a, b);
    case JointType::Weld: return create(world, done.weld, a, b);
    case JointType::Wheel: return create(world, done.wheel, a, b);
    case JointType::Motor: return create(world, done.motor, a, b);
    case JointType::Mouse: return create(world, done.mouse, a, b);
  }
  return JointId{};
}

}  // namespace impulse2d::demos

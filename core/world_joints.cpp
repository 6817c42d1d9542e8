// World's joint API: creation (validated, generation-checked handles), destruction (also with
// a body), reaction force and torque, and the pairs whose contacts jointed bodies skip.
#include "core/world.h"

#include "core/error.h"
#include "core/solver/world_state.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace impulse2d {

namespace {

std::string describe(JointId id) {
  return "joint {index " + std::to_string(id.index) + ", generation " + std::to_string(id.generation) + "}";
}

bool is_living_joint(const WorldState& world, JointId id) {
  return !id.is_null() && id.index < world.joints.size() && world.joint_alive[id.index] &&
         world.joints[id.index].id.generation == id.generation;
}

const Joint& checked_joint(const WorldState& world, JointId id, const char* caller) {
  if (!is_living_joint(world, id)) {
    throw Error(std::string(caller) + ": " + describe(id) +
                (id.is_null() ? " is a null handle" : " is stale or was never created"));
  }
  return world.joints[id.index];
}

bool is_living_body(const WorldState& world, BodyId id) {
  return !id.is_null() && id.index < world.bodies.size() && world.alive[id.index] &&
         world.bodies[id.index].id.generation == id.generation;
}

void wake(Body& body) {
  if (body.type == BodyType::Static) return;
  body.awake = true;
  body.sleep_time = 0.0f;
}

// Checks the common fields and fills them into a new joint record.
class JointCheck {
 public:
  JointCheck(const WorldState& world, const char* caller) : world_(world), caller_(caller) {}

  void bodies(BodyId a, BodyId b) {
    for (BodyId id : {a, b}) {
      if (!is_living_body(world_, id)) {
        throw Error(std::string(caller_) + ": body {index " + std::to_string(id.index) +
                    ", generation " + std::to_string(id.generation) + "} " +
                    (id.is_null() ? "is a null handle" : "is stale or was never created"));
      }
    }
    if (a == b) throw Error(std::string(caller_) + ": body_a and body_b are the same body");
  }
  void finite(float value, const char* name) const {
    if (!std::isfinite(value)) throw Error(std::string(caller_) + ": " + name + " is not finite");
  }
  void finite(vec2 value, const char* name) const {
    if (!is_finite(value)) throw Error(std::string(caller_) + ": " + name + " is not finite");
  }
  void non_negative(float value, const char* name) const {
    if (!(std::isfinite(value) && value >= 0.0f)) {
      throw Error(std::string(caller_) + ": " + name + " must be finite and >= 0 (got " +
                  std::to_string(value) + ")");
    }
  }
  void ordered(float lower, float upper, const char* names) const {
    finite(lower, names);
    finite(upper, names);
    if (lower > upper) throw Error(std::string(caller_) + ": " + names + ": lower > upper");
  }
  vec2 unit(vec2 axis, const char* name) const {
    finite(axis, name);
    const float length = std::sqrt(length_squared(axis));
    if (!(length > 0.0f)) throw Error(std::string(caller_) + ": " + name + " must not be zero");
    return axis * (1.0f / length);
  }

 private:
  const WorldState& world_;
  const char* caller_;
};

// Checks a definition part by part (in the order of its fields) and fills the joint record.
class JointBuilder {
 public:
  template <class Def>
  JointBuilder(const WorldState& world, const char* caller, JointType type, const Def& def)
      : check_(world, caller) {
    check_.bodies(def.body_a, def.body_b);
    joint_.type = type;
    joint_.body_a = def.body_a;
    joint_.body_b = def.body_b;
    joint_.collide_connected = def.collide_connected;
    joint_.user_data = def.user_data;
  }

  const JointCheck& check() const { return check_; }
  Joint& joint() { return joint_; }

  void anchors(vec2 local_anchor_a, vec2 local_anchor_b) {
    check_.finite(local_anchor_a, "local_anchor_a");
    check_.finite(local_anchor_b, "local_anchor_b");
    joint_.local_anchor_a = local_anchor_a;
    joint_.local_anchor_b = local_anchor_b;
  }
  void reference_angle(float angle) {
    check_.finite(angle, "reference_angle");
    joint_.reference_angle = angle;
  }
  void spring(bool enable, float hertz, float damping_ratio) {
    check_.non_negative(hertz, "hertz");
    check_.non_negative(damping_ratio, "damping_ratio");
    joint_.enable_spring = enable;
    joint_.hertz = hertz;
    joint_.damping_ratio = damping_ratio;
  }
  void limit(bool enable, float lower, float upper, const char* names) {
    check_.ordered(lower, upper, names);
    joint_.enable_limit = enable;
    joint_.lower = lower;
    joint_.upper = upper;
  }
  void motor(bool enable, float speed, float max_motor, const char* max_name) {
    check_.finite(speed, "motor_speed");
    check_.non_negative(max_motor, max_name);
    joint_.enable_motor = enable;
    joint_.motor_speed = speed;
    joint_.max_motor = max_motor;
  }
  void axis(vec2 local_axis_a) { joint_.local_axis_a = check_.unit(local_axis_a, "local_axis_a"); }

 private:
  JointCheck check_;
  Joint joint_;
};

JointId add_joint(WorldState& world, Joint joint) {
  std::uint32_t index;
  if (!world.free_joint_slots.empty()) {
    auto lowest = std::min_element(world.free_joint_slots.begin(), world.free_joint_slots.end());
    index = *lowest;
    world.free_joint_slots.erase(lowest);
  } else {
    index = static_cast<std::uint32_t>(world.joints.size());
    world.joints.emplace_back();
    world.joint_alive.push_back(0);
  }
  joint.id = JointId{index, world.joints[index].id.generation + 1};
  world.joints[index] = joint;
  world.joint_alive[index] = 1;
  ++world.living_joint_count;
  wake(world.bodies[joint.body_b.index]);
  if (joint.type != JointType::Mouse) wake(world.bodies[joint.body_a.index]);
  if (!joint.collide_connected) world.rebuild_unconnected_pairs();
  return joint.id;
}

void destroy(WorldState& world, std::uint32_t index) {
  Joint& joint = world.joints[index];
  world.joint_alive[index] = 0;
  world.free_joint_slots.push_back(index);
  --world.living_joint_count;
  for (BodyId id : {joint.body_a, joint.body_b}) {
    if (is_living_body(world, id)) wake(world.bodies[id.index]);
  }
  joint.active = false;
  if (!joint.collide_connected) world.rebuild_unconnected_pairs();
}

}  // namespace

void WorldState::rebuild_unconnected_pairs() {
  unconnected_pairs.clear();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (!joint_alive[i] || joints[i].collide_connected) continue;
    const std::uint64_t first = std::min(joints[i].body_a.index, joints[i].body_b.index);
    const std::uint64_t second = std::max(joints[i].body_a.index, joints[i].body_b.index);
    unconnected_pairs.push_back(first << 32 | second);
  }
  std::sort(unconnected_pairs.begin(), unconnected_pairs.end());
}

void WorldState::destroy_joints_of(BodyId id) {
  for (std::uint32_t i = 0; i < joints.size(); ++i) {
    if (joint_alive[i] && (joints[i].body_a == id || joints[i].body_b == id)) destroy(*this, i);
  }
}

JointId World::create_joint(const RevoluteJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (revolute)", JointType::Revolute, def);
  build.anchors(def.local_anchor_a, def.local_anchor_b);
  build.reference_angle(def.reference_angle);
  build.spring(def.enable_spring, def.hertz, def.damping_ratio);
  build.limit(def.enable_limit, def.lower_angle, def.upper_angle, "lower_angle/upper_angle");
  build.motor(def.enable_motor, def.motor_speed, def.max_motor_torque, "max_motor_torque");
  return add_joint(*state_, build.joint());
}

JointId World::create_joint(const PrismaticJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (prismatic)", JointType::Prismatic, def);
  build.anchors(def.local_anchor_a, def.local_anchor_b);
  build.reference_angle(def.reference_angle);
  build.spring(def.enable_spring, def.hertz, def.damping_ratio);
  build.limit(def.enable_limit, def.lower_translation, def.upper_translation,
              "lower_translation/upper_translation");
  build.motor(def.enable_motor, def.motor_speed, def.max_motor_force, "max_motor_force");
  build.axis(def.local_axis_a);
  return add_joint(*state_, build.joint());
}

JointId World::create_joint(const DistanceJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (distance)", JointType::Distance, def);
  build.anchors(def.local_anchor_a, def.local_anchor_b);
  build.check().non_negative(def.length, "length");
  build.spring(def.enable_spring, def.hertz, def.damping_ratio);
  build.check().non_negative(def.min_length, "min_length");
  build.check().non_negative(def.max_length, "max_length");
  build.check().ordered(def.min_length, def.max_length, "min_length/max_length");
  build.motor(def.enable_motor, def.motor_speed, def.max_motor_force, "max_motor_force");
  Joint& joint = build.joint();
  joint.length = def.length;
  joint.enable_limit = def.enable_limit;
  // No limit: a spring or free joint ranges freely; a rigid one holds the rest length.
  joint.min_length = def.enable_limit ? def.min_length : 0.0f;
  joint.max_length = def.enable_limit ? def.max_length : 1e30f;
  return add_joint(*state_, joint);
}

JointId World::create_joint(const WeldJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (weld)", JointType::Weld, def);
  build.anchors(def.local_anchor_a, def.local_anchor_b);
  build.reference_angle(def.reference_angle);
  const JointCheck& check = build.check();
  check.non_negative(def.linear_hertz, "linear_hertz");
  check.non_negative(def.angular_hertz, "angular_hertz");
  check.non_negative(def.linear_damping_ratio, "linear_damping_ratio");
  check.non_negative(def.angular_damping_ratio, "angular_damping_ratio");
  Joint& joint = build.joint();
  joint.linear_hertz = def.linear_hertz;
  joint.angular_hertz = def.angular_hertz;
  joint.linear_damping_ratio = def.linear_damping_ratio;
  joint.angular_damping_ratio = def.angular_damping_ratio;
  return add_joint(*state_, joint);
}

JointId World::create_joint(const WheelJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (wheel)", JointType::Wheel, def);
  build.anchors(def.local_anchor_a, def.local_anchor_b);
  build.spring(def.enable_spring, def.hertz, def.damping_ratio);
  build.limit(def.enable_limit, def.lower_translation, def.upper_translation,
              "lower_translation/upper_translation");
  build.motor(def.enable_motor, def.motor_speed, def.max_motor_torque, "max_motor_torque");
  build.axis(def.local_axis_a);
  return add_joint(*state_, build.joint());
}

JointId World::create_joint(const MotorJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (motor)", JointType::Motor, def);
  const JointCheck& check = build.check();
  check.finite(def.linear_offset, "linear_offset");
  check.finite(def.angular_offset, "angular_offset");
  check.non_negative(def.max_force, "max_force");
  check.non_negative(def.max_torque, "max_torque");
  check.non_negative(def.correction_factor, "correction_factor");
  if (def.correction_factor > 1.0f) {
    throw Error("World::create_joint (motor): correction_factor must be in [0, 1]");
  }
  Joint& joint = build.joint();
  joint.local_anchor_a = def.linear_offset;  // B's centre is driven to this point of A
  joint.reference_angle = def.angular_offset;
  joint.max_force = def.max_force;
  joint.max_torque = def.max_torque;
  joint.correction_factor = def.correction_factor;
  return add_joint(*state_, joint);
}

JointId World::create_joint(const MouseJointDef& def) {
  JointBuilder build(*state_, "World::create_joint (mouse)", JointType::Mouse, def);
  const JointCheck& check = build.check();
  check.finite(def.local_anchor_b, "local_anchor_b");
  check.finite(def.target, "target");
  check.non_negative(def.hertz, "hertz");
  if (!(def.hertz > 0.0f)) throw Error("World::create_joint (mouse): hertz must be > 0");
  check.non_negative(def.damping_ratio, "damping_ratio");
  check.non_negative(def.max_force, "max_force");
  Joint& joint = build.joint();
  joint.local_anchor_b = def.local_anchor_b;
  joint.target = def.target;
  joint.hertz = def.hertz;
  joint.damping_ratio = def.damping_ratio;
  joint.max_force = def.max_force;
  return add_joint(*state_, joint);
}

void World::destroy_joint(JointId id) {
  checked_joint(*state_, id, "World::destroy_joint");
  destroy(*state_, id.index);
}

bool World::is_valid(JointId id) const { return is_living_joint(*state_, id); }

JointType World::joint_type(JointId id) const {
  return checked_joint(*state_, id, "World::joint_type").type;
}

BodyId World::joint_body_a(JointId id) const {
  return checked_joint(*state_, id, "World::joint_body_a").body_a;
}

BodyId World::joint_body_b(JointId id) const {
  return checked_joint(*state_, id, "World::joint_body_b").body_b;
}

std::vector<JointId> World::joint_ids() const {
  std::vector<JointId> ids;
  for (std::size_t i = 0; i < state_->joints.size(); ++i) {
    if (state_->joint_alive[i]) ids.push_back(state_->joints[i].id);
  }
  return ids;
}

int World::joint_count() const { return state_->living_joint_count; }

vec2 World::joint_reaction_force(JointId id) const {
  return impulse2d::joint_reaction_force(checked_joint(*state_, id, "World::joint_reaction_force"),
                                         state_->bodies);
}

float World::joint_reaction_torque(JointId id) const {
  return impulse2d::joint_reaction_torque(checked_joint(*state_, id, "World::joint_reaction_torque"));
}

void World::set_mouse_target(JointId id, vec2 target) {
  if (!is_finite(target)) throw Error("World::set_mouse_target: target is not finite");
  const Joint& joint = checked_joint(*state_, id, "World::set_mouse_target");
  if (joint.type != JointType::Mouse) throw Error("World::set_mouse_target: " + describe(id) + " is not a mouse joint");
  state_->joints[id.index].target = target;
  wake(state_->bodies[joint.body_b.index]);
}

void World::set_joint_motor_speed(JointId id, float speed) {
  if (!std::isfinite(speed)) throw Error("World::set_joint_motor_speed: speed is not finite");
  const Joint& joint = checked_joint(*state_, id, "World::set_joint_motor_speed");
  if (joint.type != JointType::Revolute && joint.type != JointType::Prismatic &&
      joint.type != JointType::Wheel && joint.type != JointType::Distance) {
    throw Error("World::set_joint_motor_speed: " + describe(id) + " has no motor");
  }
  state_->joints[id.index].motor_speed = speed;
  wake(state_->bodies[joint.body_a.index]);
  wake(state_->bodies[joint.body_b.index]);
}

}  // namespace impulse2d

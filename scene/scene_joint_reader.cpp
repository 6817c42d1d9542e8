/// @file scene_joint_reader.cpp
#include "scene/scene_joint_reader.h"

#include <algorithm>

#include "scene/scene_limits.h"

namespace impulse2d::demos {
namespace {

int read_joint_body(const JsonCursor& node, const JointBodies& bodies) {
  int index = -1;
  if (node.value().is_string()) {
    const std::string name = node.string();
    const auto found = bodies.names->find(name);
    if (found == bodies.names->end()) node.fail("unknown body \"" + name + "\"");
    index = found->second;
  } else {
    index = static_cast<int>(node.integer(0, 1000000));
  }
  if (index >= bodies.count) {
    node.fail("body " + std::to_string(index) + " does not exist (" + std::to_string(bodies.count) +
              " bodies can be named here)");
  }
  return index;
}

std::string body_label(const JsonCursor& node) {
  return node.value().is_string() ? "\"" + node.string() + "\"" : node.value().dump();
}

float hertz_of(const JsonCursor& node) { return node.in_range(0.0f, 1000.0f, "Hz"); }
float ratio_of(const JsonCursor& node) { return node.in_range(0.0f, 1000.0f, "a damping ratio, 1 = critical"); }
float force_of(const JsonCursor& node) { return node.in_range(0.0f, limits::max_force, limits::force_reason); }
float speed_of(const JsonCursor& node) { return node.magnitude_at_most(limits::max_speed, limits::speed_reason); }
vec2 point_of(const JsonCursor& node) { return node.vector_at_most(limits::max_coordinate, limits::coordinate_reason); }

struct Spring {
  float hertz = 0.0f;
  float damping_ratio = 0.0f;
};

Spring read_spring(const JsonCursor& node) {
  node.allow_only({"hertz", "damping_ratio"});
  Spring spring;
  spring.hertz = hertz_of(node.field("hertz"));
  if (auto field = node.optional_field("damping_ratio")) spring.damping_ratio = ratio_of(*field);
  return spring;
}

struct Motor {
  float speed = 0.0f;
  float max = 0.0f;
};

// `max_name` is "max_torque" (revolute, wheel) or "max_force" (prismatic, distance).
Motor read_motor(const JsonCursor& node, const char* max_name) {
  node.allow_only({"speed", max_name});
  Motor motor;
  motor.speed = speed_of(node.field("speed"));
  motor.max = force_of(node.field(max_name));
  return motor;
}

// [lower, upper]; `angles`: radians, else metres.
std::pair<float, float> read_limits(const JsonCursor& node, bool angles) {
  if (node.size() != 2) node.fail("expected [lower, upper]");
  const auto one = [angles](const JsonCursor& value) {
    return angles ? value.magnitude_at_most(1e4f, "rad")
                  : value.magnitude_at_most(limits::max_coordinate, limits::coordinate_reason);
  };
  const float lower = one(node.element(0));
  const float upper = one(node.element(1));
  if (lower > upper) {
    node.fail("the limits are reversed: lower " + compact_number(lower) + " is above upper " +
              compact_number(upper) + " (write [lower, upper])");
  }
  return {lower, upper};
}

// The optional "spring" of `node` into a definition with enable_spring, hertz, damping_ratio.
template <class Def>
void read_spring_part(const JsonCursor& node, Def& def) {
  if (auto field = node.optional_field("spring")) {
    const Spring spring = read_spring(*field);
    def.enable_spring = true;
    def.hertz = spring.hertz;
    def.damping_ratio = spring.damping_ratio;
  }
}

// The optional "motor" of `node` into a definition with enable_motor and motor_speed, and its
// limit into `max` (torque or force, named `max_name` in the file).
template <class Def>
void read_motor_part(const JsonCursor& node, const char* max_name, Def& def, float& max) {
  if (auto field = node.optional_field("motor")) {
    const Motor motor = read_motor(*field, max_name);
    def.enable_motor = true;
    def.motor_speed = motor.speed;
    max = motor.max;
  }
}

// The optional "limits" of `node` into a definition with enable_limit and `lower`, `upper`.
template <class Def>
void read_limits_part(const JsonCursor& node, bool angles, Def& def, float& lower, float& upper) {
  if (auto field = node.optional_field("limits")) {
    std::tie(lower, upper) = read_limits(*field, angles);
    def.enable_limit = true;
  }
}

vec2 read_axis(const JsonCursor& node) {
  const vec2 axis = node.vector_at_most(1e4f, "a direction");
  if (!(axis.x != 0.0f || axis.y != 0.0f)) node.fail("the axis must not be zero");
  return axis;
}

// The body's bounds as declared, grown by its own size: an anchor outside this is "far".
bool near_body(const BodySpawn& body, vec2 point) {
  const Transform place{body.def.position, Rotation::from_angle(body.def.angle)};
  Aabb box = compute_aabb(body.shape, place);
  for (std::size_t i = 0; i < body.shapes.size(); ++i) {  // a compound body: all its shapes
    const ShapeDef& part = body.shapes[i];
    const Aabb each = compute_aabb(part.shape, Transform{place.apply(part.position),
                                                         Rotation::from_angle(body.def.angle + part.angle)});
    box = i == 0 ? each : Aabb{glm::min(box.lower, each.lower), glm::max(box.upper, each.upper)};
  }
  const vec2 size = box.upper - box.lower;
  const float margin = std::max({size.x, size.y, 0.1f});
  return point.x >= box.lower.x - margin && point.x <= box.upper.x + margin && point.y >= box.lower.y - margin &&
         point.y <= box.upper.y + margin;
}

std::string point_text(vec2 p) { return "(" + compact_number(p.x) + ", " + compact_number(p.y) + ")"; }

}  // namespace

JointSpec read_joint(const JsonCursor& node, const JointBodies& bodies, std::vector<std::string>& warnings,
                     const std::string& file) {
  node.expect_object();
  JointSpec spec;
  spec.origin = node.path();
  const JsonCursor type = node.field("type");
  spec.type = type.choice<JointType>({{"revolute", JointType::Revolute},
                                      {"prismatic", JointType::Prismatic},
                                      {"distance", JointType::Distance},
                                      {"weld", JointType::Weld},
                                      {"wheel", JointType::Wheel},
                                      {"motor", JointType::Motor},
                                      {"mouse", JointType::Mouse}});
  switch (spec.type) {
    case JointType::Revolute:
      node.allow_only({"type", "name", "bodies", "anchor", "anchors", "limits", "motor", "spring",
                       "collide_connected"});
      break;
    case JointType::Prismatic:
      node.allow_only({"type", "name", "bodies", "anchor", "anchors", "axis", "limits", "motor", "spring",
                       "collide_connected"});
      break;
    case JointType::Distance:
      node.allow_only({"type", "name", "bodies", "anchor", "anchors", "length", "min_length", "max_length",
                       "spring", "motor", "collide_connected"});
      break;
    case JointType::Weld:
      node.allow_only({"type", "name", "bodies", "anchor", "anchors", "linear_hertz", "angular_hertz",
                       "linear_damping_ratio", "angular_damping_ratio", "collide_connected"});
      break;
    case JointType::Wheel:
      node.allow_only({"type", "name", "bodies", "anchor", "anchors", "axis", "limits", "motor", "spring",
                       "collide_connected"});
      break;
    case JointType::Motor:
      node.allow_only({"type", "name", "bodies", "linear_offset", "angular_offset", "max_force", "max_torque",
                       "correction_factor", "collide_connected"});
      break;
    case JointType::Mouse:
      node.allow_only({"type", "name", "body", "target", "anchor", "hertz", "damping_ratio", "max_force",
                       "collide_connected"});
      break;
  }
  if (auto field = node.optional_field("name")) {
    spec.name = field->string();
    if (spec.name.empty()) field->fail("a joint name must not be empty (leave \"name\" out for an unnamed joint)");
  }
  if (auto field = node.optional_field("collide_connected")) spec.collide_connected = field->boolean();

  // The bodies.
  std::string label_a, label_b;
  if (spec.type == JointType::Mouse) {
    const JsonCursor body = node.field("body");
    spec.body_b = read_joint_body(body, bodies);
    label_b = body_label(body);
    // Body A only anchors the joint: the first static body the file declares.
    for (int i = 0; i < bodies.count && spec.body_a < 0; ++i) {
      const BodySpawn* each = bodies.spawn ? bodies.spawn(i) : nullptr;
      if (each != nullptr && each->def.type == BodyType::Static) spec.body_a = i;
    }
    if (spec.body_a < 0) {
      node.fail("a mouse joint holds on to the scene's first static body, and the scene has none "
                "(add a static body, e.g. the ground)");
    }
    if (spec.body_a == spec.body_b) body.fail("a mouse joint cannot drag a static body");
  } else {
    const JsonCursor list = node.field("bodies");
    if (list.size() != 2) list.fail("expected two bodies [A, B], got " + std::to_string(list.size()));
    spec.body_a = read_joint_body(list.element(0), bodies);
    spec.body_b = read_joint_body(list.element(1), bodies);
    label_a = body_label(list.element(0));
    label_b = body_label(list.element(1));
    if (spec.body_a == spec.body_b) {
      list.element(1).fail("the joint connects body " + label_b + " to itself (a joint needs two different bodies)");
    }
  }

  // Anchors: one shared world point ("anchor") or one per body ("anchors").
  const bool anchored = spec.type != JointType::Motor && spec.type != JointType::Mouse;
  if (anchored) {
    const bool one = node.has("anchor");
    const bool two = node.has("anchors");
    if (one && two) node.field("anchors").fail("give either \"anchor\" (one world point) or \"anchors\" (one per body)");
    if (one) {
      spec.anchor_a = spec.anchor_b = point_of(node.field("anchor"));
    } else if (two) {
      const JsonCursor list = node.field("anchors");
      if (list.size() != 2) list.fail("expected [[x, y] on A, [x, y] on B]");
      spec.anchor_a = point_of(list.element(0));
      spec.anchor_b = point_of(list.element(1));
    } else if (spec.type == JointType::Distance) {
      node.fail("missing field \"anchors\" (a distance joint joins one world point on each body)");
    } else {
      node.fail("missing field \"anchor\" (the world point where the bodies are joined)");
    }
  }

  switch (spec.type) {
    case JointType::Revolute: {
      RevoluteJointDef& def = spec.revolute;
      read_limits_part(node, true, def, def.lower_angle, def.upper_angle);
      read_motor_part(node, "max_torque", def, def.max_motor_torque);
      read_spring_part(node, def);
      break;
    }
    case JointType::Prismatic: {
      PrismaticJointDef& def = spec.prismatic;
      spec.axis = read_axis(node.field("axis"));
      read_limits_part(node, false, def, def.lower_translation, def.upper_translation);
      read_motor_part(node, "max_force", def, def.max_motor_force);
      read_spring_part(node, def);
      break;
    }
    case JointType::Distance: {
      DistanceJointDef& def = spec.distance;
      const auto length = [](const JsonCursor& field) {
        return field.in_range(0.0f, limits::max_coordinate, limits::coordinate_reason);
      };
      if (auto field = node.optional_field("length")) {
        def.length = length(*field);
        if (def.length < 0.005f) field->fail("must be at least 0.005 m, got " + compact_number(def.length));
        spec.has_length = true;
      }
      if (node.has("min_length") || node.has("max_length")) def.enable_limit = true;
      if (auto field = node.optional_field("min_length")) def.min_length = length(*field);
      if (auto field = node.optional_field("max_length")) {
        def.max_length = length(*field);
        if (def.max_length < def.min_length) {
          field->fail("the limits are reversed: max_length " + compact_number(def.max_length) +
                      " is below min_length " + compact_number(def.min_length));
        }
      }
      read_spring_part(node, def);
      read_motor_part(node, "max_force", def, def.max_motor_force);
      break;
    }
    case JointType::Weld: {
      WeldJointDef& def = spec.weld;
      if (auto field = node.optional_field("linear_hertz")) def.linear_hertz = hertz_of(*field);
      if (auto field = node.optional_field("angular_hertz")) def.angular_hertz = hertz_of(*field);
      if (auto field = node.optional_field("linear_damping_ratio")) def.linear_damping_ratio = ratio_of(*field);
      if (auto field = node.optional_field("angular_damping_ratio")) def.angular_damping_ratio = ratio_of(*field);
      break;
    }
    case JointType::Wheel: {
      WheelJointDef& def = spec.wheel;
      spec.axis = read_axis(node.field("axis"));
      read_limits_part(node, false, def, def.lower_translation, def.upper_translation);
      read_motor_part(node, "max_torque", def, def.max_motor_torque);
      read_spring_part(node, def);
      def.enable_spring = def.enable_spring && def.hertz > 0.0f;  // "hertz": 0 is no suspension
      break;
    }
    case JointType::Motor: {
      MotorJointDef& def = spec.motor;
      if (auto field = node.optional_field("linear_offset")) def.linear_offset = point_of(*field);
      if (auto field = node.optional_field("angular_offset")) def.angular_offset = field->magnitude_at_most(1e4f, "rad");
      if (auto field = node.optional_field("max_force")) def.max_force = force_of(*field);
      if (auto field = node.optional_field("max_torque")) def.max_torque = force_of(*field);
      if (auto field = node.optional_field("correction_factor")) {
        def.correction_factor = field->in_range(0.0f, 1.0f, "the fraction of the pose error closed per step");
      }
      break;
    }
    case JointType::Mouse: {
      MouseJointDef& def = spec.mouse;
      def.target = point_of(node.field("target"));
      if (auto field = node.optional_field("hertz")) {
        def.hertz = hertz_of(*field);
        if (!(def.hertz > 0.0f)) field->fail("must be > 0 (a mouse joint is a spring), got 0");
      }
      if (auto field = node.optional_field("damping_ratio")) def.damping_ratio = ratio_of(*field);
      if (auto field = node.optional_field("max_force")) def.max_force = force_of(*field);
      if (auto field = node.optional_field("anchor")) {
        spec.anchor_b = point_of(*field);
      } else {
        spec.anchor_b_is_center = true;
      }
      break;
    }
  }

  // Warnings: an anchor far outside both of its bodies as declared is probably a body-local
  // point written where a world point belongs.
  if (bodies.spawn) {
    const BodySpawn* body_a = spec.type == JointType::Mouse ? nullptr : bodies.spawn(spec.body_a);
    const BodySpawn* body_b = bodies.spawn(spec.body_b);
    const auto far = [&](vec2 point, const BodySpawn* first, const BodySpawn* second) {
      if (first == nullptr && second == nullptr) return false;
      return !(first != nullptr && near_body(*first, point)) && !(second != nullptr && near_body(*second, point));
    };
    const auto warn = [&](const std::string& field, vec2 point, const std::string& which) {
      warnings.push_back(file + ": " + node.path() + "." + field + ": the anchor " + point_text(point) +
                         " is far outside " + which +
                         " as declared (anchors are world points where the joint is created, not body-local)");
    };
    if (anchored && node.has("anchor") && far(spec.anchor_a, body_a, body_b)) {
      warn("anchor", spec.anchor_a, "both bodies " + label_a + " and " + label_b);
    } else if (anchored && node.has("anchors")) {
      if (far(spec.anchor_a, body_a, nullptr)) {
        warn("anchors[0]", spec.anchor_a, "body " + label_a);
      }
      if (far(spec.anchor_b, body_b, nullptr)) {
        warn("anchors[1]", spec.anchor_b, "body " + label_b);
      }
    } else if (spec.type == JointType::Mouse && node.has("anchor") && far(spec.anchor_b, body_b, nullptr)) {
      warn("anchor", spec.anchor_b, "body " + label_b);
    }
  }
  return spec;
}

}  // namespace impulse2d::demos

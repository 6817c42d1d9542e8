// World::draw's joints overlay (draw_joints): for each living joint, in slot order, its anchors
// on both bodies and the line between them, prismatic and wheel axes with their limit stops,
// revolute limit arcs with the current angle's pointer, spring coils, the motor's direction
// and the reaction force on body B as an arrow on the impulse arrows' scale.
#include "core/solver/world_state.h"
#include "core/world.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

constexpr float kPi = 3.14159265f;
constexpr float kMaxMarkRadius = 0.3f;   // limit arcs and motor arcs, metres, at most
constexpr int kArcSegments = 12;

Transform drawn_pose(const Body& body, float alpha) {
  const vec2 position = body.previous_position * (1.0f - alpha) + body.transform.position * alpha;
  const float angle = body.previous_angle * (1.0f - alpha) + body.angle * alpha;
  return Transform{position, Rotation::from_angle(angle)};
}

float drawn_angle(const Body& body, float alpha) { return body.previous_angle * (1.0f - alpha) + body.angle * alpha; }

vec2 direction(float angle) {
  const Rotation rotation = Rotation::from_angle(angle);
  return rotation.x_axis();
}

// An arc about `center` from world angle `from` to `to` (radians), as segments.
void draw_arc(DebugDraw& draw, vec2 center, float radius, float from, float to, Color color) {
  vec2 previous = center + direction(from) * radius;
  for (int i = 1; i <= kArcSegments; ++i) {
    const float angle = from + (to - from) * static_cast<float>(i) / static_cast<float>(kArcSegments);
    const vec2 next = center + direction(angle) * radius;
    draw.draw_segment(previous, next, color);
    previous = next;
  }
}

// A spring coil (zig-zag) from `from` to `to`.
void draw_coil(DebugDraw& draw, vec2 from, vec2 to, Color color) {
  const vec2 along = to - from;
  const float length = std::sqrt(along.x * along.x + along.y * along.y);
  if (!(length > 1e-4f)) return;
  const vec2 unit = along / length;
  const vec2 side(-unit.y, unit.x);
  const float amplitude = std::min(0.12f, 0.2f * length);
  constexpr int kTeeth = 10;
  // Straight ends of a tenth each, the coil between.
  const vec2 start = from + along * 0.1f;
  const vec2 end = from + along * 0.9f;
  draw.draw_segment(from, start, color);
  vec2 previous = start;
  for (int i = 1; i <= kTeeth; ++i) {
    const float t = (static_cast<float>(i) - 0.5f) / static_cast<float>(kTeeth);
    const vec2 next = start + (end - start) * t + side * (i % 2 == 0 ? -amplitude : amplitude);
    draw.draw_segment(previous, next, color);
    previous = next;
  }
  draw.draw_segment(previous, end, color);
  draw.draw_segment(end, to, color);
}

// A short stroke across `axis` at `point` (a limit stop).
void draw_stop(DebugDraw& draw, vec2 point, vec2 axis, Color color) {
  const vec2 side(-axis.y, axis.x);
  draw.draw_segment(point - side * 0.12f, point + side * 0.12f, color);
}

// A curved arrow about `center` turning counter-clockwise for `speed` > 0, clockwise below.
void draw_turn(DebugDraw& draw, vec2 center, float start_angle, float speed, float kMarkRadius, Color color) {
  if (speed == 0.0f) return;
  const float sweep = speed > 0.0f ? 0.5f * kPi : -0.5f * kPi;
  const float radius = 0.6f * kMarkRadius;
  draw_arc(draw, center, radius, start_angle, start_angle + 0.85f * sweep, color);
  draw.draw_arrow(center + direction(start_angle + 0.85f * sweep) * radius,
                  center + direction(start_angle + sweep) * radius, color);
}

}  // namespace

void draw_world_joints(const WorldState& state, DebugDraw& draw, const DebugDrawOptions& options) {
  const float alpha = std::clamp(options.interpolation_alpha, 0.0f, 1.0f);
  const Color color = options.palette.joint;
  const Color reaction_color = options.palette.joint_reaction;
  const float step = state.settings.time_step;
  for (std::size_t slot = 0; slot < state.joints.size(); ++slot) {
    if (!state.joint_alive[slot]) continue;
    const Joint& joint = state.joints[slot];
    const Body& body_a = state.bodies[joint.body_a.index];
    const Body& body_b = state.bodies[joint.body_b.index];
    const Transform pose_a = drawn_pose(body_a, alpha);
    const Transform pose_b = drawn_pose(body_b, alpha);
    const vec2 anchor_a = pose_a.apply(joint.local_anchor_a);
    const vec2 anchor_b = pose_b.apply(joint.local_anchor_b);
    const float angle_a = drawn_angle(body_a, alpha);
    const float angle_b = drawn_angle(body_b, alpha);
    // Marks no larger than a third of the smaller body's longest side (small ragdoll limbs).
    const auto longest = [](const Body& body) {
      return std::max(body.aabb.upper.x - body.aabb.lower.x, body.aabb.upper.y - body.aabb.lower.y);
    };
    const float kMarkRadius = std::min(kMaxMarkRadius, std::max(0.05f, longest(body_a) < longest(body_b)
                                                                            ? longest(body_a) / 3.0f
                                                                            : longest(body_b) / 3.0f));
    switch (joint.type) {
      case JointType::Revolute: {
        draw.draw_segment(pose_a.position, anchor_a, color);
        draw.draw_segment(pose_b.position, anchor_b, color);
        if (joint.enable_limit) {
          const float zero = angle_a + joint.reference_angle;
          draw_arc(draw, anchor_a, kMarkRadius, zero + joint.lower, zero + joint.upper, color);
          draw.draw_segment(anchor_a, anchor_a + direction(zero + joint.lower) * kMarkRadius, color);
          draw.draw_segment(anchor_a, anchor_a + direction(zero + joint.upper) * kMarkRadius, color);
          // The current joint angle: a pointer along B's zero direction.
          draw.draw_segment(anchor_b, anchor_b + direction(angle_b) * (1.3f * kMarkRadius), color);
        }
        if (joint.enable_spring && joint.hertz > 0.0f) {
          draw_arc(draw, anchor_a, 0.45f * kMarkRadius, angle_b, angle_b + 1.5f * kPi, color);
        }
        if (joint.enable_motor) draw_turn(draw, anchor_b, angle_b + 0.5f * kPi, joint.motor_speed, kMarkRadius, color);
        break;
      }
      case JointType::Prismatic:
      case JointType::Wheel: {
        const vec2 axis = pose_a.rotation.rotate(joint.local_axis_a);
        const float lower = joint.enable_limit ? joint.lower : -0.5f;
        const float upper = joint.enable_limit ? joint.upper : 0.5f;
        draw.draw_segment(anchor_a + axis * std::min(lower, -0.2f), anchor_a + axis * std::max(upper, 0.2f), color);
        if (joint.enable_limit) {
          draw_stop(draw, anchor_a + axis * joint.lower, axis, color);
          draw_stop(draw, anchor_a + axis * joint.upper, axis, color);
        }
        draw.draw_segment(pose_a.position, anchor_a, color);
        if (joint.enable_spring && joint.hertz > 0.0f) {
          draw_coil(draw, anchor_a, anchor_b, color);
        } else {
          draw.draw_segment(anchor_a, anchor_b, color);
        }
        if (joint.enable_motor) {
          if (joint.type == JointType::Wheel) {
            draw_turn(draw, anchor_b, angle_b + 0.5f * kPi, joint.motor_speed, kMarkRadius, color);
          } else if (joint.motor_speed != 0.0f) {
            const vec2 push = axis * (joint.motor_speed > 0.0f ? kMarkRadius : -kMarkRadius);
            const vec2 side(-axis.y * 0.1f, axis.x * 0.1f);
            draw.draw_arrow(anchor_b + side, anchor_b + side + push, color);
          }
        }
        break;
      }
      case JointType::Distance: {
        draw.draw_segment(pose_a.position, anchor_a, color);
        draw.draw_segment(pose_b.position, anchor_b, color);
        if (joint.enable_spring && joint.hertz > 0.0f) {
          draw_coil(draw, anchor_a, anchor_b, color);
        } else {
          draw.draw_segment(anchor_a, anchor_b, color);
        }
        const vec2 along = anchor_b - anchor_a;
        const float length = std::sqrt(along.x * along.x + along.y * along.y);
        if (joint.enable_limit && length > 1e-4f) {
          const vec2 unit = along / length;
          if (joint.min_length > 0.0f) draw_stop(draw, anchor_a + unit * joint.min_length, unit, color);
          if (joint.max_length < 1000.0f) draw_stop(draw, anchor_a + unit * joint.max_length, unit, color);
        }
        if (joint.enable_motor && joint.motor_speed != 0.0f && length > 1e-4f) {
          const vec2 unit = along / length;
          draw.draw_arrow(anchor_b, anchor_b + unit * (joint.motor_speed > 0.0f ? kMarkRadius : -kMarkRadius), color);
        }
        break;
      }
      case JointType::Weld: {
        draw.draw_segment(pose_a.position, anchor_a, color);
        draw.draw_segment(pose_b.position, anchor_b, color);
        const float r = 0.5f * kMarkRadius;
        const vec2 u = direction(angle_a + 0.25f * kPi) * r;
        const vec2 v = direction(angle_a + 0.75f * kPi) * r;
        draw.draw_segment(anchor_a - u, anchor_a + u, color);
        draw.draw_segment(anchor_a - v, anchor_a + v, color);
        break;
      }
      case JointType::Motor: {
        const vec2 target = pose_a.apply(joint.linear_offset);
        draw.draw_segment(pose_a.position, target, color);
        draw.draw_segment(target, pose_b.position, color);
        draw.draw_point(target, 6.0f, color);
        draw.draw_segment(pose_b.position, pose_b.position + direction(angle_a + joint.angular_offset) * kMarkRadius,
                          color);
        break;
      }
      case JointType::Mouse: {
        draw_coil(draw, joint.target, anchor_b, color);
        const float r = 0.5f * kMarkRadius;
        draw.draw_segment(joint.target - vec2(r, 0.0f), joint.target + vec2(r, 0.0f), color);
        draw.draw_segment(joint.target - vec2(0.0f, r), joint.target + vec2(0.0f, r), color);
        break;
      }
    }
    if (joint.type != JointType::Motor && joint.type != JointType::Mouse) draw.draw_point(anchor_a, 7.0f, color);
    if (joint.type != JointType::Motor) draw.draw_point(anchor_b, 5.0f, color);
    // Reaction on B: the force over one step as an impulse arrow (the contact impulses' scale).
    const vec2 force = joint_reaction_force(joint, state.bodies);
    if (force.x != 0.0f || force.y != 0.0f) {
      const vec2 from = joint.type == JointType::Motor ? pose_b.position : anchor_b;
      draw.draw_arrow(from, from + force * (step * options.impulse_scale), reaction_color);
    }
  }
}

}  // namespace impulse2d

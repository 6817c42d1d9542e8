// The joints' scalar solve (joint_solver.h). Every constraint is written on a `JointBody` pair so
// the soft step (on `SolverBody` states) and the other two methods (on `Body`s) share one code.
// Conventions: r_a, r_b are the anchors from the centres of mass in world axes; the constraint
// velocity Cdot is the rate of the position error C; an impulse is applied +B / -A.
#include "core/solver/joint_solver.h"

#include "core/solver/integrate.h"
#include "core/settings.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

float inverse_or_zero(float k) { return k > 0.0f ? 1.0f / k : 0.0f; }

// x solving [k11 k12; k12 k22] x = b (0 for a singular matrix).
vec2 solve22(float k11, float k12, float k22, vec2 b) {
  float det = k11 * k22 - k12 * k12;
  if (det != 0.0f) det = 1.0f / det;
  return vec2(det * (k22 * b.x - k12 * b.y), det * (k11 * b.y - k12 * b.x));
}

// A symmetric 3x3 matrix by its upper triangle, and a 3-vector.
struct Matrix33 {
  float k11, k12, k13, k22, k23, k33;
};
struct Vector3 {
  float x, y, z;
};

// x solving K x = b by Cramer's rule (0 for a singular matrix; K symmetric).
Vector3 solve33(const Matrix33& k, const Vector3& b) {
  // Cofactors of the symmetric matrix.
  const float c11 = k.k22 * k.k33 - k.k23 * k.k23;
  const float c12 = k.k13 * k.k23 - k.k12 * k.k33;
  const float c13 = k.k12 * k.k23 - k.k13 * k.k22;
  const float c22 = k.k11 * k.k33 - k.k13 * k.k13;
  const float c23 = k.k12 * k.k13 - k.k11 * k.k23;
  const float c33 = k.k11 * k.k22 - k.k12 * k.k12;
  float det = k.k11 * c11 + k.k12 * c12 + k.k13 * c13;
  if (det != 0.0f) det = 1.0f / det;
  return {det * (c11 * b.x + c12 * b.y + c13 * b.z), det * (c12 * b.x + c22 * b.y + c23 * b.z),
          det * (c13 * b.x + c23 * b.y + c33 * b.z)};
}

struct Anchors {
  vec2 r_a;  // metres, world axes
  vec2 r_b;
};

Anchors anchors_of(const Joint& joint, const JointBody& a, const JointBody& b) {
  return {a.rotation.rotate(joint.local_anchor_a), b.rotation.rotate(joint.local_anchor_b)};
}

// Separation of the anchors, B's minus A's, metres.
vec2 separation(const JointBody& a, const JointBody& b, const Anchors& r) {
  return (b.position + r.r_b) - (a.position + r.r_a);
}

vec2 relative_velocity(const JointBody& a, const JointBody& b, const Anchors& r) {
  return b.velocity + cross(b.angular_velocity, r.r_b) - a.velocity - cross(a.angular_velocity, r.r_a);
}

void apply_linear(const Joint& joint, JointBody& a, JointBody& b, const Anchors& r, vec2 impulse) {
  a.velocity -= impulse * joint.inverse_mass_a;
  a.angular_velocity -= joint.inverse_inertia_a * cross(r.r_a, impulse);
  b.velocity += impulse * joint.inverse_mass_b;
  b.angular_velocity += joint.inverse_inertia_b * cross(r.r_b, impulse);
}

void apply_angular(const Joint& joint, JointBody& a, JointBody& b, float impulse) {
  a.angular_velocity -= joint.inverse_inertia_a * impulse;
  b.angular_velocity += joint.inverse_inertia_b * impulse;
}

// An impulse along `axis` whose angular arms are `arm_a` (A) and `arm_b` (B).
void apply_axial(const Joint& joint, JointBody& a, JointBody& b, vec2 axis, float arm_a,
                 float arm_b, float impulse) {
  a.velocity -= axis * (joint.inverse_mass_a * impulse);
  a.angular_velocity -= joint.inverse_inertia_a * arm_a * impulse;
  b.velocity += axis * (joint.inverse_mass_b * impulse);
  b.angular_velocity += joint.inverse_inertia_b * arm_b * impulse;
}

float angular_mass(const Joint& joint) {
  return inverse_or_zero(joint.inverse_inertia_a + joint.inverse_inertia_b);
}

float joint_angle(const Joint& joint, const JointBody& a, const JointBody& b) {
  return b.angle - a.angle - joint.reference_angle;
}

// A one-sided limit C >= 0 whose rate is `cdot`, with effective mass `mass`. Open (C > 0), it
// lets the gap close within the step (speculative); violated, it stops the approach rigidly and
// pushes back at the joint softness's bias rate (solve) or not at all (relax). Returns the
// impulse to apply; keeps the running total >= 0 (accumulated) or each pass's impulse >= 0
// (per-iteration).
// The velocity part is rigid, not soft as Box2D v3's: a soft limit is a spring of stiffness
// mass * (2 pi f)^2 (f the joint hertz), so a motor (or any force F) parked against it pushes
// it F / (mass (2 pi f)^2) past the limit: 0.22 m for 1000 N on a 31 g slider at 60 Hz, the
// overshoot measured before this. Rigid, the limit takes back in each pass what the motor
// solved just before it added, whatever the motor's force.
float limit_impulse(float c, float cdot, float mass, float& accumulated, const JointPass& pass) {
  float bias = 0.0f;
  if (c > 0.0f) {
    bias = c / pass.h;
  } else if (pass.use_bias) {
    bias = pass.joint_softness.bias_rate * c;
  }
  float impulse = -mass * (cdot + bias);
  if (pass.accumulate) {
    const float total = std::max(accumulated + impulse, 0.0f);
    impulse = total - accumulated;
    accumulated = total;
  } else {
    impulse = std::max(impulse, 0.0f);
    accumulated += impulse;
  }
  return impulse;
}

// A soft spring on C with rate `cdot` (always biased: the user's spring is physical).
float spring_impulse(const Softness& soft, float c, float cdot, float mass, float& accumulated) {
  const float impulse =
      -mass * soft.mass_scale * (cdot + soft.bias_rate * c) - soft.impulse_scale * accumulated;
  accumulated += impulse;
  return impulse;
}

// A motor driving `cdot` to 0 with at most `max_impulse` in total this (sub-)step.
float motor_impulse(float cdot, float mass, float max_impulse, float& accumulated) {
  const float old = accumulated;
  accumulated = std::clamp(old - mass * cdot, -max_impulse, max_impulse);
  return accumulated - old;
}

// The rigid point constraint (revolute, weld) on the 2x2 effective mass; `soft` is the bias's.
void solve_point(Joint& joint, JointBody& a, JointBody& b, const Anchors& r, const Softness& soft,
                 bool biased) {
  const vec2 cdot = relative_velocity(a, b, r);
  vec2 bias(0.0f);
  float mass_scale = 1.0f;
  float impulse_scale = 0.0f;
  if (biased) {
    bias = separation(a, b, r) * soft.bias_rate;
    mass_scale = soft.mass_scale;
    impulse_scale = soft.impulse_scale;
  }
  const float ma = joint.inverse_mass_a, mb = joint.inverse_mass_b;
  const float ia = joint.inverse_inertia_a, ib = joint.inverse_inertia_b;
  const float k11 = ma + mb + r.r_a.y * r.r_a.y * ia + r.r_b.y * r.r_b.y * ib;
  const float k12 = -r.r_a.y * r.r_a.x * ia - r.r_b.y * r.r_b.x * ib;
  const float k22 = ma + mb + r.r_a.x * r.r_a.x * ia + r.r_b.x * r.r_b.x * ib;
  const vec2 solution = solve22(k11, k12, k22, cdot + bias);
  const vec2 impulse = -solution * mass_scale - joint.linear_impulse * impulse_scale;
  joint.linear_impulse += impulse;
  apply_linear(joint, a, b, r, impulse);
}

// ---- per type ---------------------------------------------------------------------------

void solve_revolute(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  const float mass = angular_mass(joint);
  if (joint.enable_spring && joint.hertz > 0.0f && pass.use_bias) {
    const float impulse = spring_impulse(joint.spring_softness, joint_angle(joint, a, b),
                                         b.angular_velocity - a.angular_velocity, mass,
                                         joint.spring_impulse);
    apply_angular(joint, a, b, impulse);
  }
  if (joint.enable_motor) {
    const float impulse =
        motor_impulse(b.angular_velocity - a.angular_velocity - joint.motor_speed, mass,
                      pass.h * joint.max_motor, joint.motor_impulse);
    apply_angular(joint, a, b, impulse);
  }
  if (joint.enable_limit) {
    const float angle = joint_angle(joint, a, b);
    float impulse = limit_impulse(angle - joint.lower, b.angular_velocity - a.angular_velocity, mass,
                                  joint.lower_impulse, pass);
    apply_angular(joint, a, b, impulse);
    impulse = limit_impulse(joint.upper - angle, a.angular_velocity - b.angular_velocity, mass,
                            joint.upper_impulse, pass);
    apply_angular(joint, a, b, -impulse);
  }
  solve_point(joint, a, b, anchors_of(joint, a, b), pass.joint_softness, pass.use_bias);
}

// A rigid weld: the point and the angle as one 3x3 block (Box2D 2.4.1's rigid weld), so a load's
// moment is held by the whole lever's inertia (the point rows) and not the angle row's alone: a
// disc welded 1 m out from a wall turns 5e-5 rad under its weight where the separate rows let
// it turn 3.5e-3 (the disc's own inertia against the moment).
void solve_rigid_weld(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  const Anchors r = anchors_of(joint, a, b);
  const vec2 cdot_point = relative_velocity(a, b, r);
  const float cdot_angle = b.angular_velocity - a.angular_velocity;
  vec2 bias_point(0.0f);
  float bias_angle = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
  if (pass.use_bias) {
    const Softness& soft = pass.joint_softness;
    bias_point = separation(a, b, r) * soft.bias_rate;
    bias_angle = joint_angle(joint, a, b) * soft.bias_rate;
    mass_scale = soft.mass_scale;
    impulse_scale = soft.impulse_scale;
  }
  const float ma = joint.inverse_mass_a, mb = joint.inverse_mass_b;
  const float ia = joint.inverse_inertia_a, ib = joint.inverse_inertia_b;
  const Matrix33 k{ma + mb + r.r_a.y * r.r_a.y * ia + r.r_b.y * r.r_b.y * ib,
                   -r.r_a.y * r.r_a.x * ia - r.r_b.y * r.r_b.x * ib,
                   -r.r_a.y * ia - r.r_b.y * ib,
                   ma + mb + r.r_a.x * r.r_a.x * ia + r.r_b.x * r.r_b.x * ib,
                   r.r_a.x * ia + r.r_b.x * ib,
                   ia + ib};
  const Vector3 solution =
      solve33(k, {cdot_point.x + bias_point.x, cdot_point.y + bias_point.y, cdot_angle + bias_angle});
  const vec2 linear = vec2(solution.x, solution.y) * -mass_scale - joint.linear_impulse * impulse_scale;
  const float angular = -solution.z * mass_scale - joint.angular_impulse * impulse_scale;
  joint.linear_impulse += linear;
  joint.angular_impulse += angular;
  apply_linear(joint, a, b, r, linear);
  apply_angular(joint, a, b, angular);
}

void solve_weld(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  if (joint.linear_hertz <= 0.0f && joint.angular_hertz <= 0.0f) {
    solve_rigid_weld(joint, a, b, pass);
    return;
  }
  {
    const bool spring = joint.angular_hertz > 0.0f;
    const Softness& soft = spring ? joint.angular_softness : pass.joint_softness;
    float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
    if (pass.use_bias || spring) {
      bias = soft.bias_rate * joint_angle(joint, a, b);
      mass_scale = soft.mass_scale;
      impulse_scale = soft.impulse_scale;
    }
    const float cdot = b.angular_velocity - a.angular_velocity;
    const float impulse =
        -angular_mass(joint) * mass_scale * (cdot + bias) - impulse_scale * joint.angular_impulse;
    joint.angular_impulse += impulse;
    apply_angular(joint, a, b, impulse);
  }
  const bool spring = joint.linear_hertz > 0.0f;
  solve_point(joint, a, b, anchors_of(joint, a, b),
              spring ? joint.spring_softness : pass.joint_softness, pass.use_bias || spring);
}

// Axis geometry of prismatic and wheel joints.
struct AxisFrame {
  Anchors r;
  vec2 d;          // anchor separation, metres
  vec2 axis;       // world axis (A's)
  vec2 perp;       // axis turned +90 degrees
  float a1, a2;    // arms of an impulse along the axis
  float s1, s2;    // arms of an impulse along perp
  float translation;  // metres along the axis
};

AxisFrame axis_frame(const Joint& joint, const JointBody& a, const JointBody& b) {
  AxisFrame f;
  f.r = anchors_of(joint, a, b);
  f.d = separation(a, b, f.r);
  f.axis = a.rotation.rotate(joint.local_axis_a);
  f.perp = left_perpendicular(f.axis);
  f.a1 = cross(f.d + f.r.r_a, f.axis);
  f.a2 = cross(f.r.r_b, f.axis);
  f.s1 = cross(f.d + f.r.r_a, f.perp);
  f.s2 = cross(f.r.r_b, f.perp);
  f.translation = glm::dot(f.axis, f.d);
  return f;
}

float axial_rate(const JointBody& a, const JointBody& b, vec2 axis, float arm_a,
                 float arm_b) {
  return glm::dot(axis, b.velocity - a.velocity) + arm_b * b.angular_velocity -
         arm_a * a.angular_velocity;
}

float axial_mass(const Joint& joint, float arm_a, float arm_b) {
  return inverse_or_zero(joint.inverse_mass_a + joint.inverse_mass_b +
                         joint.inverse_inertia_a * arm_a * arm_a +
                         joint.inverse_inertia_b * arm_b * arm_b);
}

// Spring, motor (linear: prismatic) and limits along the axis of prismatic and wheel joints.
void solve_axis_parts(Joint& joint, JointBody& a, JointBody& b, const AxisFrame& f,
                      const JointPass& pass, bool linear_motor) {
  const float mass = axial_mass(joint, f.a1, f.a2);
  if (joint.enable_spring && joint.hertz > 0.0f && pass.use_bias) {
    const float impulse = spring_impulse(joint.spring_softness, f.translation,
                                         axial_rate(a, b, f.axis, f.a1, f.a2), mass,
                                         joint.spring_impulse);
    apply_axial(joint, a, b, f.axis, f.a1, f.a2, impulse);
  }
  if (joint.enable_motor && linear_motor) {
    const float impulse = motor_impulse(axial_rate(a, b, f.axis, f.a1, f.a2) - joint.motor_speed,
                                        mass, pass.h * joint.max_motor, joint.motor_impulse);
    apply_axial(joint, a, b, f.axis, f.a1, f.a2, impulse);
  }
  if (joint.enable_limit) {
    float impulse = limit_impulse(f.translation - joint.lower, axial_rate(a, b, f.axis, f.a1, f.a2),
                                  mass, joint.lower_impulse, pass);
    apply_axial(joint, a, b, f.axis, f.a1, f.a2, impulse);
    impulse = limit_impulse(joint.upper - f.translation, -axial_rate(a, b, f.axis, f.a1, f.a2),
                            mass, joint.upper_impulse, pass);
    apply_axial(joint, a, b, f.axis, f.a1, f.a2, -impulse);
  }
}

void solve_prismatic(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  const AxisFrame f = axis_frame(joint, a, b);
  solve_axis_parts(joint, a, b, f, pass, /*linear_motor=*/true);
  // Perpendicular and angular together (2x2).
  const vec2 cdot(axial_rate(a, b, f.perp, f.s1, f.s2), b.angular_velocity - a.angular_velocity);
  vec2 bias(0.0f);
  float mass_scale = 1.0f, impulse_scale = 0.0f;
  if (pass.use_bias) {
    bias = vec2(glm::dot(f.perp, f.d), joint_angle(joint, a, b)) * pass.joint_softness.bias_rate;
    mass_scale = pass.joint_softness.mass_scale;
    impulse_scale = pass.joint_softness.impulse_scale;
  }
  const float ma = joint.inverse_mass_a, mb = joint.inverse_mass_b;
  const float ia = joint.inverse_inertia_a, ib = joint.inverse_inertia_b;
  const float k11 = ma + mb + ia * f.s1 * f.s1 + ib * f.s2 * f.s2;
  const float k12 = ia * f.s1 + ib * f.s2;
  float k22 = ia + ib;
  if (k22 == 0.0f) k22 = 1.0f;  // neither turns: the angular row is idle
  const vec2 accumulated(joint.linear_impulse.x, joint.angular_impulse);
  const vec2 impulse = -solve22(k11, k12, k22, cdot + bias) * mass_scale - accumulated * impulse_scale;
  joint.linear_impulse.x += impulse.x;
  joint.angular_impulse += impulse.y;
  apply_axial(joint, a, b, f.perp, f.s1, f.s2, impulse.x);
  apply_angular(joint, a, b, impulse.y);
}

void solve_wheel(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  if (joint.enable_motor) {
    const float impulse =
        motor_impulse(b.angular_velocity - a.angular_velocity - joint.motor_speed, angular_mass(joint),
                      pass.h * joint.max_motor, joint.motor_impulse);
    apply_angular(joint, a, b, impulse);
  }
  const AxisFrame f = axis_frame(joint, a, b);
  solve_axis_parts(joint, a, b, f, pass, /*linear_motor=*/false);
  // Point on the line.
  float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
  if (pass.use_bias) {
    bias = pass.joint_softness.bias_rate * glm::dot(f.perp, f.d);
    mass_scale = pass.joint_softness.mass_scale;
    impulse_scale = pass.joint_softness.impulse_scale;
  }
  const float cdot = axial_rate(a, b, f.perp, f.s1, f.s2);
  const float impulse = -axial_mass(joint, f.s1, f.s2) * mass_scale * (cdot + bias) -
                        impulse_scale * joint.linear_impulse.x;
  joint.linear_impulse.x += impulse;
  apply_axial(joint, a, b, f.perp, f.s1, f.s2, impulse);
}

void solve_distance(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  const Anchors r = anchors_of(joint, a, b);
  const vec2 d = separation(a, b, r);
  const float length = std::sqrt(length_squared(d));
  const vec2 axis = length > 0.0f ? d * (1.0f / length) : vec2(1.0f, 0.0f);
  const float arm_a = cross(r.r_a, axis);
  const float arm_b = cross(r.r_b, axis);
  const float mass = axial_mass(joint, arm_a, arm_b);
  auto rate = [&] { return glm::dot(axis, relative_velocity(a, b, r)); };
  const bool free_range = joint.enable_spring && joint.min_length < joint.max_length;
  if (free_range && joint.hertz > 0.0f && pass.use_bias) {
    const float impulse =
        spring_impulse(joint.spring_softness, length - joint.length, rate(), mass, joint.spring_impulse);
    apply_axial(joint, a, b, axis, arm_a, arm_b, impulse);
  }
  if (joint.enable_motor) {
    const float impulse = motor_impulse(rate() - joint.motor_speed, mass, pass.h * joint.max_motor,
                                        joint.motor_impulse);
    apply_axial(joint, a, b, axis, arm_a, arm_b, impulse);
  }
  if (joint.enable_limit && joint.min_length < joint.max_length) {
    float impulse = limit_impulse(length - joint.min_length, rate(), mass, joint.lower_impulse, pass);
    apply_axial(joint, a, b, axis, arm_a, arm_b, impulse);
    impulse = limit_impulse(joint.max_length - length, -rate(), mass, joint.upper_impulse, pass);
    apply_axial(joint, a, b, axis, arm_a, arm_b, -impulse);
  }
  if (!free_range) {
    // Rigid at the rest length (or at min = max).
    const float target = joint.enable_spring ? joint.min_length : joint.length;
    float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
    if (pass.use_bias) {
      bias = pass.joint_softness.bias_rate * (length - target);
      mass_scale = pass.joint_softness.mass_scale;
      impulse_scale = pass.joint_softness.impulse_scale;
    }
    const float impulse = -mass * mass_scale * (rate() + bias) - impulse_scale * joint.axial_impulse;
    joint.axial_impulse += impulse;
    apply_axial(joint, a, b, axis, arm_a, arm_b, impulse);
  }
}

void solve_motor_joint(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  const float drive_rate = joint.correction_factor / pass.h;
  {
    const float c = joint_angle(joint, a, b);  // reference_angle holds the angular offset
    const float impulse = motor_impulse(b.angular_velocity - a.angular_velocity + drive_rate * c,
                                        angular_mass(joint), pass.h * joint.max_torque,
                                        joint.angular_impulse);
    apply_angular(joint, a, b, impulse);
  }
  const Anchors r = anchors_of(joint, a, b);  // A's anchor is the offset, B's its centre
  const vec2 cdot = relative_velocity(a, b, r) + separation(a, b, r) * drive_rate;
  const float ma = joint.inverse_mass_a, mb = joint.inverse_mass_b;
  const float ia = joint.inverse_inertia_a, ib = joint.inverse_inertia_b;
  const float k11 = ma + mb + r.r_a.y * r.r_a.y * ia + r.r_b.y * r.r_b.y * ib;
  const float k12 = -r.r_a.y * r.r_a.x * ia - r.r_b.y * r.r_b.x * ib;
  const float k22 = ma + mb + r.r_a.x * r.r_a.x * ia + r.r_b.x * r.r_b.x * ib;
  const vec2 old = joint.linear_impulse;
  vec2 total = old - solve22(k11, k12, k22, cdot);
  const float max_impulse = pass.h * joint.max_force;
  const float size_squared = length_squared(total);
  if (size_squared > max_impulse * max_impulse) total *= max_impulse / std::sqrt(size_squared);
  joint.linear_impulse = total;
  apply_linear(joint, a, b, r, total - old);
}

void solve_mouse(Joint& joint, JointBody& b, const JointPass& pass) {
  const float ib = joint.inverse_inertia_b, mb = joint.inverse_mass_b;
  {
    // Angular damping without a target, so a dragged body does not spin up (Box2D's).
    const Softness& soft = joint.angular_softness;
    const float impulse = -soft.mass_scale * inverse_or_zero(ib) * b.angular_velocity -
                          soft.impulse_scale * joint.angular_impulse;
    joint.angular_impulse += impulse;
    b.angular_velocity += ib * impulse;
  }
  const vec2 r_b = b.rotation.rotate(joint.local_anchor_b);
  const vec2 cdot = b.velocity + cross(b.angular_velocity, r_b);
  const Softness& soft = joint.spring_softness;
  const vec2 bias = (b.position + r_b - joint.target) * soft.bias_rate;
  const float k11 = mb + r_b.y * r_b.y * ib;
  const float k12 = -r_b.y * r_b.x * ib;
  const float k22 = mb + r_b.x * r_b.x * ib;
  const vec2 old = joint.linear_impulse;
  vec2 total = old - solve22(k11, k12, k22, cdot + bias) * soft.mass_scale - old * soft.impulse_scale;
  const float max_impulse = pass.h * joint.max_force;
  const float size_squared = length_squared(total);
  if (size_squared > max_impulse * max_impulse) total *= max_impulse / std::sqrt(size_squared);
  joint.linear_impulse = total;
  const vec2 impulse = total - old;
  b.velocity += impulse * mb;
  b.angular_velocity += ib * cross(r_b, impulse);
}

void solve_joint(Joint& joint, JointBody& a, JointBody& b, const JointPass& pass) {
  switch (joint.type) {
    case JointType::Revolute: solve_revolute(joint, a, b, pass); return;
    case JointType::Prismatic: solve_prismatic(joint, a, b, pass); return;
    case JointType::Distance: solve_distance(joint, a, b, pass); return;
    case JointType::Weld: solve_weld(joint, a, b, pass); return;
    case JointType::Wheel: solve_wheel(joint, a, b, pass); return;
    case JointType::Motor: solve_motor_joint(joint, a, b, pass); return;
    case JointType::Mouse: solve_mouse(joint, b, pass); return;
  }
}

void warm_start_joint(Joint& joint, JointBody& a, JointBody& b) {
  const float axial = joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse;
  switch (joint.type) {
    case JointType::Revolute: {
      apply_linear(joint, a, b, anchors_of(joint, a, b), joint.linear_impulse);
      apply_angular(joint, a, b, axial);
      return;
    }
    case JointType::Weld:
    case JointType::Motor: {
      apply_linear(joint, a, b, anchors_of(joint, a, b), joint.linear_impulse);
      apply_angular(joint, a, b, joint.angular_impulse);
      return;
    }
    case JointType::Prismatic:
    case JointType::Wheel: {
      const AxisFrame f = axis_frame(joint, a, b);
      apply_axial(joint, a, b, f.perp, f.s1, f.s2, joint.linear_impulse.x);
      if (joint.type == JointType::Prismatic) {
        apply_angular(joint, a, b, joint.angular_impulse);
        apply_axial(joint, a, b, f.axis, f.a1, f.a2, axial);
      } else {
        apply_angular(joint, a, b, joint.motor_impulse);
        apply_axial(joint, a, b, f.axis, f.a1, f.a2, axial - joint.motor_impulse);
      }
      return;
    }
    case JointType::Distance: {
      const Anchors r = anchors_of(joint, a, b);
      const vec2 d = separation(a, b, r);
      const float length = std::sqrt(length_squared(d));
      const vec2 axis = length > 0.0f ? d * (1.0f / length) : vec2(1.0f, 0.0f);
      apply_axial(joint, a, b, axis, cross(r.r_a, axis), cross(r.r_b, axis), axial + joint.axial_impulse);
      return;
    }
    case JointType::Mouse: {
      const vec2 r_b = b.rotation.rotate(joint.local_anchor_b);
      b.velocity += joint.linear_impulse * joint.inverse_mass_b;
      b.angular_velocity += joint.inverse_inertia_b * (cross(r_b, joint.linear_impulse) + joint.angular_impulse);
      return;
    }
  }
}

JointBody load(const SolverBody& state) {
  JointBody body;
  body.velocity = vec2(state.velocity_x, state.velocity_y);
  body.angular_velocity = state.angular_velocity;
  body.position = vec2(state.position_x, state.position_y);
  body.rotation = Rotation{state.cosine, state.sine};
  body.angle = state.angle;
  return body;
}

void store(const JointBody& body, SolverBody& state) {
  state.velocity_x = body.velocity.x;
  state.velocity_y = body.velocity.y;
  state.angular_velocity = body.angular_velocity;
}

JointBody load(const Body& source) {
  JointBody body;
  body.velocity = source.linear_velocity;
  body.angular_velocity = source.angular_velocity;
  body.position = source.transform.position;
  body.rotation = source.transform.rotation;
  body.angle = source.angle;
  return body;
}

void store(const JointBody& body, Body& target) {
  target.linear_velocity = body.velocity;
  target.angular_velocity = body.angular_velocity;
}

// Runs `work(joint, a, b)` on every active joint, loading and storing the two bodies (a body
// that does not move this step is only read).
template <class States, class Work>
void for_each_active(std::vector<Joint>& joints, States& states, Work work) {
  for (Joint& joint : joints) {
    if (!joint.active) continue;
    auto& state_a = states[joint.body_a.index];
    auto& state_b = states[joint.body_b.index];
    JointBody a = load(state_a);
    JointBody b = load(state_b);
    work(joint, a, b);
    if (joint.inverse_mass_a != 0.0f || joint.inverse_inertia_a != 0.0f) store(a, state_a);
    if (joint.inverse_mass_b != 0.0f || joint.inverse_inertia_b != 0.0f) store(b, state_b);
  }
}

}  // namespace

void prepare_joints(std::vector<Joint>& joints, const std::vector<std::uint8_t>& joint_alive,
                    const std::vector<Body>& bodies, const WorldSettings& settings, float h,
                    bool clear_impulses) {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    Joint& joint = joints[i];
    joint.active = false;
    if (!joint_alive[i]) continue;
    const Body& a = bodies[joint.body_a.index];
    const Body& b = bodies[joint.body_b.index];
    const bool a_moves = a.type == BodyType::Dynamic && a.awake && joint.type != JointType::Mouse;
    const bool b_moves = b.type == BodyType::Dynamic && b.awake;
    joint.inverse_mass_a = a_moves ? a.inverse_mass : 0.0f;
    joint.inverse_inertia_a = a_moves ? effective_inverse_inertia(a, settings) : 0.0f;
    joint.inverse_mass_b = b_moves ? b.inverse_mass : 0.0f;
    joint.inverse_inertia_b = b_moves ? effective_inverse_inertia(b, settings) : 0.0f;
    joint.active = a_moves || b_moves;
    joint.impulse_interval = h;
    if (clear_impulses || !joint.active) {
      joint.linear_impulse = vec2(0.0f);
      joint.angular_impulse = joint.axial_impulse = joint.spring_impulse = 0.0f;
      joint.motor_impulse = joint.lower_impulse = joint.upper_impulse = 0.0f;
    }
    if (!joint.active) continue;
    switch (joint.type) {
      case JointType::Weld:
        if (joint.linear_hertz > 0.0f) {
          joint.spring_softness = make_soft(joint.linear_hertz, joint.linear_damping_ratio, h);
        }
        if (joint.angular_hertz > 0.0f) {
          joint.angular_softness = make_soft(joint.angular_hertz, joint.angular_damping_ratio, h);
        }
        break;
      case JointType::Mouse:
        joint.spring_softness = make_soft(joint.hertz, joint.damping_ratio, h);
        joint.angular_softness = make_soft(0.5f, 0.1f, h);  // Box2D v3's drag damping
        break;
      default:
        if (joint.hertz > 0.0f) joint.spring_softness = make_soft(joint.hertz, joint.damping_ratio, h);
        break;
    }
  }
}

void warm_start_joints(std::vector<Joint>& joints, SolverBody* states) {
  for_each_active(joints, states, [](Joint& joint, JointBody& a, JointBody& b) { warm_start_joint(joint, a, b); });
}

void solve_joints(std::vector<Joint>& joints, SolverBody* states, const JointPass& pass) {
  for_each_active(joints, states,
                  [&pass](Joint& joint, JointBody& a, JointBody& b) { solve_joint(joint, a, b, pass); });
}

void warm_start_joints(std::vector<Joint>& joints, std::vector<Body>& bodies) {
  for_each_active(joints, bodies, [](Joint& joint, JointBody& a, JointBody& b) { warm_start_joint(joint, a, b); });
}

void solve_joints(std::vector<Joint>& joints, std::vector<Body>& bodies, const JointPass& pass) {
  for_each_active(joints, bodies,
                  [&pass](Joint& joint, JointBody& a, JointBody& b) { solve_joint(joint, a, b, pass); });
}

vec2 joint_reaction_force(const Joint& joint, const std::vector<Body>& bodies) {
  if (!joint.active || joint.impulse_interval <= 0.0f) return vec2(0.0f);
  const float inverse_interval = 1.0f / joint.impulse_interval;
  const Body& a = bodies[joint.body_a.index];
  const Body& b = bodies[joint.body_b.index];
  const float axial = joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse;
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Weld:
    case JointType::Motor:
    case JointType::Mouse:
      return joint.linear_impulse * inverse_interval;
    case JointType::Prismatic:
    case JointType::Wheel: {
      const vec2 axis = a.transform.rotation.rotate(joint.local_axis_a);
      const float along = joint.type == JointType::Wheel ? axial - joint.motor_impulse : axial;
      return (left_perpendicular(axis) * joint.linear_impulse.x + axis * along) * inverse_interval;
    }
    case JointType::Distance: {
      const vec2 d = b.transform.apply(joint.local_anchor_b) - a.transform.apply(joint.local_anchor_a);
      const float length = std::sqrt(length_squared(d));
      const vec2 axis = length > 0.0f ? d * (1.0f / length) : vec2(1.0f, 0.0f);
      return axis * ((axial + joint.axial_impulse) * inverse_interval);
    }
  }
  return vec2(0.0f);
}

float joint_reaction_torque(const Joint& joint) {
  if (!joint.active || joint.impulse_interval <= 0.0f) return 0.0f;
  const float inverse_interval = 1.0f / joint.impulse_interval;
  switch (joint.type) {
    case JointType::Revolute:
      return (joint.spring_impulse + joint.motor_impulse + joint.lower_impulse - joint.upper_impulse) *
             inverse_interval;
    case JointType::Wheel: return joint.motor_impulse * inverse_interval;
    case JointType::Distance: return 0.0f;
    default: return joint.angular_impulse * inverse_interval;
  }
}

}  // namespace impulse2d

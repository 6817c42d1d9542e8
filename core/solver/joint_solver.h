#pragma once
/// @file joint_solver.h
/// The world's joints (internal) and their scalar solve, shared by the three solver methods:
/// prepare once per (sub-)step sequence, warm start, solve passes with the soft bias (and the
/// soft step's relax passes without it), in joint slot order (deterministic). The method is
/// Box2D v3's soft constraints (Catto, "Solver2D" and `joint.c`): each constraint is a
/// spring-damper with an implicit-Euler softness (`softness.h`); rigid parts use the world's
/// joint softness (twice the contact hertz, damping ratio 2), which the relax pass drops.

#include "core/joint.h"
#include "core/settings.h"
#include "core/solver/body_state.h"
#include "core/solver/softness.h"
#include "core/solver/solver_body.h"

#include <cstdint>
#include <vector>

namespace impulse2d {

struct SolverContext;

/// One joint as the world keeps it: its definition (all types in one record) and its
/// accumulated impulses (warm start) and prepared values.
struct Joint {
  JointId id;                            ///< this joint's handle
  JointType type = JointType::Revolute;  ///< which constraint
  BodyId body_a;                         ///< first body
  BodyId body_b;                         ///< second body
  vec2 local_anchor_a{0.0f, 0.0f};       ///< metres from A's centre of mass, A's frame
  vec2 local_anchor_b{0.0f, 0.0f};       ///< metres from B's centre of mass, B's frame
  vec2 local_axis_a{1.0f, 0.0f};         ///< unit, A's frame (prismatic, wheel)
  float reference_angle = 0.0f;          ///< radians
  bool collide_connected = false;        ///< contacts between A and B solved
  bool enable_spring = false;            ///< spring part on
  bool enable_limit = false;             ///< limit part on
  bool enable_motor = false;             ///< motor part on
  float hertz = 0.0f;                    ///< spring Hz (mouse: pull)
  float damping_ratio = 0.0f;            ///< spring damping ratio
  float lower = 0.0f;                    ///< limit: radians (revolute) or metres
  float upper = 0.0f;                    ///< limit: radians (revolute) or metres
  float motor_speed = 0.0f;              ///< rad/s or m/s
  float max_motor = 0.0f;                ///< N m or N
  float length = 1.0f;                   ///< distance: rest length, metres
  float min_length = 0.0f;               ///< distance, metres
  float max_length = 0.0f;               ///< distance, metres
  float linear_hertz = 0.0f;             ///< weld, Hz
  float angular_hertz = 0.0f;            ///< weld, Hz
  float linear_damping_ratio = 0.0f;     ///< weld
  float angular_damping_ratio = 0.0f;    ///< weld
  vec2 linear_offset{0.0f, 0.0f};        ///< motor joint, metres in A's frame
  float angular_offset = 0.0f;           ///< motor joint, radians
  float max_force = 0.0f;                ///< motor and mouse joints, N
  float max_torque = 0.0f;               ///< motor joint, N m
  float correction_factor = 0.0f;        ///< motor joint
  vec2 target{0.0f, 0.0f};               ///< mouse, world metres
  std::uint64_t user_data = 0;           ///< the caller's value

  // Accumulated impulses (N s, N m s), per sub-step: the warm start of the next one.
  vec2 linear_impulse{0.0f, 0.0f};  ///< point/weld/motor/mouse (x: perpendicular for prismatic, wheel)
  float angular_impulse = 0.0f;     ///< weld, prismatic, motor, mouse angular parts
  float axial_impulse = 0.0f;       ///< rigid distance
  float spring_impulse = 0.0f;      ///< spring part
  float motor_impulse = 0.0f;       ///< motor part
  float lower_impulse = 0.0f;       ///< lower limit (>= 0)
  float upper_impulse = 0.0f;       ///< upper limit (>= 0)

  // Prepared for the step.
  float inverse_mass_a = 0.0f;      ///< 0 unless A moves this step
  float inverse_mass_b = 0.0f;      ///< 0 unless B moves this step
  float inverse_inertia_a = 0.0f;   ///< effective
  float inverse_inertia_b = 0.0f;   ///< effective
  Softness spring_softness;         ///< the user's spring over the sub-step
  Softness angular_softness;        ///< weld angular / mouse angular damping
  float impulse_interval = 0.0f;    ///< seconds an accumulated impulse acts over (reaction = impulse / it)
  bool active = false;              ///< solved this step (some body moves)
};

/// The per-body view a joint solve works on: velocity (changed) and pose (read).
struct JointBody {
  vec2 velocity{0.0f, 0.0f};  ///< m/s
  float angular_velocity = 0.0f;  ///< rad/s
  vec2 position{0.0f, 0.0f};  ///< centre of mass, metres
  Rotation rotation;          ///< orientation
  float angle = 0.0f;         ///< unwrapped, radians
};

/// How a solve pass treats the joints.
struct JointPass {
  float h = 0.0f;             ///< seconds of the (sub-)step
  Softness joint_softness;    ///< of the rigid parts' position bias
  bool use_bias = true;       ///< false: the relax pass (rigid parts without position bias)
  /// false: the per-iteration solver's form: a limit's impulse is clamped per pass (a pass
  /// can only push), not accumulated; nothing is warm started.
  bool accumulate = true;
};

/// Prepares every living joint for a step whose constraints act over `h`-second sub-steps:
/// marks it active when one of its bodies is awake and not static, reads inverse masses
/// (bodies that do not move count as infinitely heavy), makes the spring softnesses.
/// `clear_impulses` drops the warm start (per-iteration solver, warm starting off).
void prepare_joints(std::vector<Joint>& joints, const std::vector<std::uint8_t>& joint_alive,
                    const std::vector<Body>& bodies, const WorldSettings& settings, float h,
                    bool clear_impulses);

/// Applies every active joint's accumulated impulses to `states` (indexed by body slot).
void warm_start_joints(std::vector<Joint>& joints, SolverBody* states);
/// One solve pass over every active joint on `states`.
void solve_joints(std::vector<Joint>& joints, SolverBody* states, const JointPass& pass);
/// `warm_start_joints` on the world's bodies (accumulated and per-iteration solvers).
void warm_start_joints(std::vector<Joint>& joints, std::vector<Body>& bodies);
/// `solve_joints` on the world's bodies (accumulated and per-iteration solvers).
void solve_joints(std::vector<Joint>& joints, std::vector<Body>& bodies, const JointPass& pass);

/// Reaction force on B (N) of a joint after the last step.
vec2 joint_reaction_force(const Joint& joint, const std::vector<Body>& bodies);
/// Reaction torque on B (N m) of a joint after the last step.
float joint_reaction_torque(const Joint& joint);

}  // namespace impulse2d

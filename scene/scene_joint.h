#pragma once
/// @file scene_joint.h
/// A joint as a scene declares it: world anchors and axes taken at creation (as scene files
/// write them), turned into the core's local-anchor definitions when the joint is created.

#include <cstdint>
#include <string>

#include "core/joint.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// One joint of a scene. Bodies are creation indices (the scene's bodies in order, then
/// spawned ones); anchors and axes are world values at the moment the joint is created.
struct JointSpec {
  std::string name;                      ///< unique in the scene, or empty
  JointType type = JointType::Revolute;  ///< which joint
  int body_a = -1;                       ///< creation index of body A (mouse: the anchoring body)
  int body_b = -1;                       ///< creation index of body B (mouse: the dragged body)
  vec2 anchor_a{0.0f, 0.0f};             ///< world point on A, metres (revolute, prismatic, weld, wheel: shared)
  vec2 anchor_b{0.0f, 0.0f};             ///< world point on B, metres (mouse: the grabbed point)
  bool anchor_b_is_center = false;       ///< mouse: grab B at its centre of mass (no "anchor" given)
  vec2 axis{1.0f, 0.0f};                 ///< world direction (prismatic, wheel), normalised on creation
  bool has_length = false;               ///< distance: `length` given (else the anchors' distance)
  bool collide_connected = false;        ///< contacts between A and B solved
  /// The core's definitions with every non-anchor field set; their body handles and local
  /// anchors/axes are filled in by `create_scene_joint`. Only the one of `type` is used.
  RevoluteJointDef revolute;
  PrismaticJointDef prismatic;    ///< see `revolute`
  DistanceJointDef distance;      ///< see `revolute`
  WeldJointDef weld;              ///< see `revolute`
  WheelJointDef wheel;            ///< see `revolute`
  MotorJointDef motor;            ///< see `revolute`
  MouseJointDef mouse;            ///< see `revolute`
  std::string origin;             ///< where it was declared, for messages ("joints[2]")
};

/// "revolute", "prismatic", ... as scene files spell the type.
const char* joint_type_name(JointType type);

/// `spec` with the definition of its type completed for bodies standing as `a` and `b`: local
/// anchors and axes from the bodies' poses, reference angles from their angles (so the bodies
/// keep their relative angle), a distance joint's length from the anchors when not given,
/// `collide_connected`. The body handles are left to the caller.
JointSpec complete_joint_spec(const JointSpec& spec, const BodyView& a, const BodyView& b);

/// Creates `spec` between the living bodies `a` and `b` of `world`, completed by
/// `complete_joint_spec` from their current poses. Throws `Error` as `World::create_joint` does.
JointId create_scene_joint(World& world, const JointSpec& spec, BodyId a, BodyId b);

}  // namespace impulse2d::demos

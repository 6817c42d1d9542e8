#pragma once
/// @file lab_simulation.h
/// What the lab needs from an engine: step a scene and report every body's state, so the same
/// metric scores impulse2d and its peers (Box2D, Chipmunk) alike.

#include <stdexcept>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/scene_joint.h"

namespace impulse2d::lab {

/// The state of one body as the lab reads it (creation index order).
struct BodyState {
  vec2 position{0.0f, 0.0f};       ///< centre of mass, metres
  float angle = 0.0f;              ///< radians
  vec2 velocity{0.0f, 0.0f};       ///< m/s
  float angular_velocity = 0.0f;   ///< rad/s
  float mass = 0.0f;               ///< kg (0 for static bodies)
  float inertia = 0.0f;            ///< kg m^2 about the centre of mass (0 when it cannot turn)
  bool dynamic = false;            ///< moved by gravity and contacts
};

/// The coefficients an engine's model gives the contact between two bodies (after its mixing
/// rules): the exact answers are computed from these, so each engine is scored against the
/// exact answer of its own model.
struct ContactCoefficients {
  float static_friction = 0.0f;   ///< Coulomb coefficient while sticking
  float dynamic_friction = 0.0f;  ///< Coulomb coefficient while sliding
  float restitution = 0.0f;       ///< e
};

/// A joint of the scene as every engine builds it: the scene's joint (`spec`) with its core
/// definition completed from the bodies' poses at creation (local anchors and axis, reference
/// angle, length), exactly as `demos::create_scene_joint` completes it for impulse2d.
struct LabJoint {
  demos::JointSpec spec;           ///< the scene's joint; the definition of `spec.type` completed
  int body_a = -1;                 ///< creation index of body A
  int body_b = -1;                 ///< creation index of body B
  vec2 local_anchor_a{0.0f, 0.0f}; ///< metres, in A's frame from its centre of mass
  vec2 local_anchor_b{0.0f, 0.0f}; ///< metres, in B's frame from its centre of mass
};

/// Where the body-frame point `local` (metres from the centre of mass) of a body in `state` is.
vec2 world_point(const BodyState& state, vec2 local);

/// One run of a scene in some engine.
class LabSimulation {
 public:
  virtual ~LabSimulation() = default;
  /// Advances one step of `time_step()` seconds.
  virtual void step() = 0;
  /// Seconds per step.
  virtual float time_step() const = 0;
  /// Gravity, m/s^2.
  virtual vec2 gravity() const = 0;
  /// Number of bodies (creation indices 0 .. body_count()-1).
  virtual int body_count() const = 0;
  /// Fills `states` with every body's state, in creation order (the buffer is reused).
  virtual void read_states(std::vector<BodyState>& states) const = 0;
  /// The mixed coefficients of a contact between bodies `a` and `b` (creation indices).
  virtual ContactCoefficients coefficients(int a, int b) const = 0;
  /// A 64-bit hash of the state (equal runs give equal hashes).
  virtual unsigned long long state_hash() const = 0;
  /// The scene's joints, as this run built them (empty for a scene without joints).
  virtual const std::vector<LabJoint>& joints() const {
    static const std::vector<LabJoint> none;
    return none;
  }
  /// True once the engine reported a body that went non-finite (and restored it).
  virtual bool diverged() const { return false; }
  /// Moves body `index` (creation index) to `position` (metres), unrotated, moving at
  /// `velocity` (m/s) without spin: for scenes that recycle their bodies (bench_compare's rain).
  /// Engines that cannot throw `std::logic_error`.
  virtual void place_body(int index, vec2 position, vec2 velocity) {
    (void)index;
    (void)position;
    (void)velocity;
    throw std::logic_error("this engine's simulation cannot place bodies");
  }
};

}  // namespace impulse2d::lab

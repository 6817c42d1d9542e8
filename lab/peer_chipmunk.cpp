/// @file peer_chipmunk.cpp
/// Chipmunk 7 as a lab peer (compiled only when libchipmunk-dev is installed). Debian's
/// libchipmunk is a debug build: it prints a banner on the first space it creates, which is
/// kept off stdout here.
#include <chipmunk/chipmunk.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fcntl.h>
#include <stdexcept>
#include <string>

#include "lab/lab_peers.h"
#include "core/world.h"

namespace impulse2d::lab {
namespace {

/// cpSpaceNew with stdout pointed at /dev/null (the debug build's banner).
cpSpace* new_quiet_space() {
  std::fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  const int null_device = open("/dev/null", O_WRONLY);
  if (saved >= 0 && null_device >= 0) dup2(null_device, STDOUT_FILENO);
  cpSpace* space = cpSpaceNew();
  std::fflush(stdout);
  if (saved >= 0 && null_device >= 0) dup2(saved, STDOUT_FILENO);
  if (null_device >= 0) close(null_device);
  if (saved >= 0) close(saved);
  return space;
}

cpVect to_cp(vec2 v) { return cpv(v.x, v.y); }

[[noreturn]] void unsupported(const LabJoint& joint, const std::string& what) {
  throw std::runtime_error(std::string(demos::joint_type_name(joint.spec.type)) + " joint " +
                           (joint.spec.origin.empty() ? "" : joint.spec.origin + " ") +
                           (what.empty() ? "" : "with " + what + ": ") +
                           "not supported by Chipmunk 7.0.3");
}

/// The reduced mass of the pair (a static or infinite body counts as infinitely heavy), as
/// Box2D's b2LinearStiffness takes it.
double reduced_mass(cpBody* a, cpBody* b) {
  const double mass_a = cpBodyGetType(a) == CP_BODY_TYPE_DYNAMIC ? cpBodyGetMass(a) : 0.0;
  const double mass_b = cpBodyGetType(b) == CP_BODY_TYPE_DYNAMIC ? cpBodyGetMass(b) : 0.0;
  if (mass_a > 0.0 && mass_b > 0.0) return mass_a * mass_b / (mass_a + mass_b);
  return mass_a > 0.0 ? mass_a : mass_b;
}

/// As `reduced_mass` for moments of inertia (an infinite moment counts as infinitely heavy).
double reduced_moment(cpBody* a, cpBody* b) {
  const auto moment = [](cpBody* body) {
    const double value = cpBodyGetType(body) == CP_BODY_TYPE_DYNAMIC ? cpBodyGetMoment(body) : 0.0;
    return std::isfinite(value) ? value : 0.0;
  };
  const double moment_a = moment(a), moment_b = moment(b);
  if (moment_a > 0.0 && moment_b > 0.0) return moment_a * moment_b / (moment_a + moment_b);
  return moment_a > 0.0 ? moment_a : moment_b;
}

/// The constraints that make `joint` in Chipmunk, added to `space` (and to `made`, which frees
/// them). Chipmunk's anchors are from the body's centre of gravity, where the adapter puts its
/// origin, so the local anchors carry over; a spring of f Hz and damping ratio z is the
/// stiffness m w^2 and damping 2 m z w (w = 2 pi f) of the pair's reduced mass m.
void create_chipmunk_joint(cpSpace* space, const LabJoint& joint, cpBody* a, cpBody* b,
                           std::vector<cpConstraint*>& made) {
  const demos::JointSpec& spec = joint.spec;
  std::vector<cpConstraint*> parts;
  const double two_pi = 6.283185307179586;
  // Angular constraints between two bodies that cannot turn have nothing to act on (and
  // Chipmunk's would divide by a zero inverse moment: NaN, then its debug build aborts).
  const bool turns = reduced_moment(a, b) > 0.0;
  switch (spec.type) {
    case JointType::Revolute: {
      const RevoluteJointDef& source = spec.revolute;
      parts.push_back(cpPivotJointNew2(a, b, to_cp(source.local_anchor_a), to_cp(source.local_anchor_b)));
      // Chipmunk's angles are absolute: the joint angle is angle_b - angle_a - reference.
      if (source.enable_limit && turns) {
        parts.push_back(cpRotaryLimitJointNew(a, b, source.lower_angle + source.reference_angle,
                                              source.upper_angle + source.reference_angle));
      }
      if (source.enable_motor && turns) {
        // cpSimpleMotor drives b.w - a.w towards -rate.
        cpConstraint* motor = cpSimpleMotorNew(a, b, -source.motor_speed);
        cpConstraintSetMaxForce(motor, source.max_motor_torque);
        parts.push_back(motor);
      }
      if (source.enable_spring && source.hertz > 0.0f && turns) {
        const double omega = two_pi * source.hertz;
        const double moment = reduced_moment(a, b);
        parts.push_back(cpDampedRotarySpringNew(a, b, source.reference_angle, moment * omega * omega,
                                                2.0 * moment * source.damping_ratio * omega));
      }
      break;
    }
    case JointType::Prismatic: {
      // A groove along the axis through A's anchor (its limits, else +-1 km) and a gear of
      // ratio 1 keeping the relative angle.
      const PrismaticJointDef& source = spec.prismatic;
      if (source.enable_motor) unsupported(joint, "a motor");
      if (source.enable_spring && source.hertz > 0.0f) unsupported(joint, "a spring");
      const float length = glm::length(source.local_axis_a);
      const vec2 axis = length > 0.0f ? source.local_axis_a / length : vec2(1.0f, 0.0f);
      const float lower = source.enable_limit ? source.lower_translation : -1000.0f;
      const float upper = source.enable_limit ? source.upper_translation : 1000.0f;
      parts.push_back(cpGrooveJointNew(a, b, to_cp(source.local_anchor_a + lower * axis),
                                       to_cp(source.local_anchor_a + upper * axis),
                                       to_cp(source.local_anchor_b)));
      if (turns) parts.push_back(cpGearJointNew(a, b, source.reference_angle, 1.0));
      break;
    }
    case JointType::Distance: {
      const DistanceJointDef& source = spec.distance;
      if (source.enable_motor) unsupported(joint, "a motor");
      const cpVect anchor_a = to_cp(source.local_anchor_a), anchor_b = to_cp(source.local_anchor_b);
      if (!source.enable_spring) {
        cpConstraint* pin = cpPinJointNew(a, b, anchor_a, anchor_b);
        cpPinJointSetDist(pin, source.length);
        parts.push_back(pin);
      } else {
        if (source.hertz > 0.0f) {
          const double omega = two_pi * source.hertz;
          const double mass = reduced_mass(a, b);
          parts.push_back(cpDampedSpringNew(a, b, anchor_a, anchor_b, source.length,
                                            mass * omega * omega,
                                            2.0 * mass * source.damping_ratio * omega));
        }
        if (source.enable_limit) {
          parts.push_back(cpSlideJointNew(a, b, anchor_a, anchor_b, source.min_length,
                                          source.max_length));
        }
      }
      break;
    }
    case JointType::Weld: {
      const WeldJointDef& source = spec.weld;
      if (source.linear_hertz > 0.0f || source.angular_hertz > 0.0f) unsupported(joint, "a spring");
      parts.push_back(cpPivotJointNew2(a, b, to_cp(source.local_anchor_a), to_cp(source.local_anchor_b)));
      if (turns) parts.push_back(cpGearJointNew(a, b, source.reference_angle, 1.0));
      break;
    }
    case JointType::Wheel:
    case JointType::Motor:
    case JointType::Mouse: unsupported(joint, "");
  }
  for (cpConstraint* part : parts) {
    cpConstraintSetCollideBodies(part, spec.collide_connected ? cpTrue : cpFalse);
    cpSpaceAddConstraint(space, part);
    made.push_back(part);
  }
}

class ChipmunkSimulation : public LabSimulation {
 public:
  ChipmunkSimulation(const World& initial, const std::vector<LabJoint>& joints,
                     const LabMethod& method)
      : space_(new_quiet_space()), method_(method), gravity_(initial.settings().gravity) {
    const WorldSettings& settings = initial.settings();
    cpSpaceSetGravity(space_, cpv(gravity_.x, gravity_.y));
    cpSpaceSetIterations(space_, method.velocity_iterations);
    cpSpaceSetCollisionSlop(space_, settings.slop);
    friction_on_ = settings.enable_friction;
    restitution_on_ = settings.enable_restitution;
    for (const BodyId id : initial.body_ids()) {
      const BodyView source = initial.body(id);
      if (source.shape_count > 0) {
        throw std::runtime_error("peer chipmunk: compound bodies (several shapes) are not copied to the peers");
      }
      cpBody* body = nullptr;
      if (source.type == BodyType::Static) {
        body = cpBodyNewStatic();
      } else if (source.type == BodyType::Kinematic) {
        body = cpBodyNewKinematic();
      } else {
        const double moment = source.inverse_inertia > 0.0f ? source.inertia : INFINITY;
        body = cpBodyNew(source.mass, moment);
      }
      cpSpaceAddBody(space_, body);
      cpBodySetPosition(body, cpv(source.transform.position.x, source.transform.position.y));
      cpBodySetAngle(body, source.angle);
      cpBodySetVelocity(body, cpv(source.linear_velocity.x, source.linear_velocity.y));
      cpBodySetAngularVelocity(body, source.angular_velocity);
      cpShape* shape = nullptr;
      switch (source.shape->type()) {
        case ShapeType::Circle:
          shape = cpCircleShapeNew(body, source.shape->circle().radius, cpvzero);
          break;
        case ShapeType::Box:
          shape = cpBoxShapeNew(body, 2.0 * source.shape->box().half_extents.x,
                                2.0 * source.shape->box().half_extents.y, 0.0);
          break;
        case ShapeType::Polygon: {
          cpVect vertices[max_polygon_vertices];
          for (int i = 0; i < source.shape->polygon().count; ++i) {
            const vec2 v = source.shape->polygon().vertices[static_cast<std::size_t>(i)];
            vertices[i] = cpv(v.x, v.y);
          }
          shape = cpPolyShapeNewRaw(body, source.shape->polygon().count, vertices,
                                    source.shape->polygon().rounding);
          break;
        }
        case ShapeType::Capsule: {  // Chipmunk's segment with a radius is a capsule
          const Capsule& capsule = source.shape->capsule();
          shape = cpSegmentShapeNew(body, cpv(capsule.center1.x, capsule.center1.y),
                                    cpv(capsule.center2.x, capsule.center2.y), capsule.radius);
          break;
        }
        case ShapeType::Segment: {
          const Segment& segment = source.shape->segment();
          shape = cpSegmentShapeNew(body, cpv(segment.point1.x, segment.point1.y),
                                    cpv(segment.point2.x, segment.point2.y), 0.0);
          // A chain link: Chipmunk 7's segments are two-sided; its neighbours only smooth the
          // seams (a contact at an end cap whose normal leans towards the neighbour is dropped).
          // At an open chain's end the ghost is the end itself: a zero tangent, a free corner,
          // as in impulse2d.
          if (segment.one_sided) cpSegmentShapeSetNeighbors(shape, to_cp(segment.ghost1), to_cp(segment.ghost2));
          break;
        }
      }
      cpShapeSetFriction(shape, friction_on_ ? source.material->static_friction : 0.0);
      cpShapeSetElasticity(shape, restitution_on_ ? source.material->restitution : 0.0);
      cpSpaceAddShape(space_, shape);
      bodies_.push_back(body);
      shapes_.push_back(shape);
      materials_.push_back(*source.material);
      dynamic_.push_back(source.type == BodyType::Dynamic);
      rotates_.push_back(source.inverse_inertia > 0.0f);
    }
    try {
      for (const LabJoint& joint : joints) {
        create_chipmunk_joint(space_, joint, bodies_.at(static_cast<std::size_t>(joint.body_a)),
                              bodies_.at(static_cast<std::size_t>(joint.body_b)), constraints_);
      }
    } catch (...) {
      free_all();
      throw;
    }
    joints_ = joints;
  }
  const std::vector<LabJoint>& joints() const override { return joints_; }
  ~ChipmunkSimulation() override { free_all(); }
  ChipmunkSimulation(const ChipmunkSimulation&) = delete;
  ChipmunkSimulation& operator=(const ChipmunkSimulation&) = delete;

  void step() override {
    if (diverged_) return;
    cpSpaceStep(space_, method_.time_step);
    // Debian's debug build aborts the whole process when a body goes non-finite (a blown-up
    // joint chain gets there within steps): a body beyond 1e6 m or 1e6 m/s counts as diverged
    // and the run stops stepping, so the lab reports it instead of dying.
    for (cpBody* body : bodies_) {
      const cpVect p = cpBodyGetPosition(body), v = cpBodyGetVelocity(body);
      if (!(cpvlength(p) < 1e6 && cpvlength(v) < 1e6)) diverged_ = true;
    }
  }
  bool diverged() const override { return diverged_; }
  float time_step() const override { return method_.time_step; }
  vec2 gravity() const override { return gravity_; }
  int body_count() const override { return static_cast<int>(bodies_.size()); }
  void read_states(std::vector<BodyState>& states) const override {
    states.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      cpBody* body = bodies_[i];
      BodyState& state = states[i];
      const cpVect position = cpBodyGetPosition(body);
      const cpVect velocity = cpBodyGetVelocity(body);
      state.position = {static_cast<float>(position.x), static_cast<float>(position.y)};
      state.angle = static_cast<float>(cpBodyGetAngle(body));
      state.velocity = {static_cast<float>(velocity.x), static_cast<float>(velocity.y)};
      state.angular_velocity = static_cast<float>(cpBodyGetAngularVelocity(body));
      state.dynamic = dynamic_[i];
      state.mass = dynamic_[i] ? static_cast<float>(cpBodyGetMass(body)) : 0.0f;
      state.inertia = dynamic_[i] && rotates_[i] ? static_cast<float>(cpBodyGetMoment(body)) : 0.0f;
    }
  }
  ContactCoefficients coefficients(int a, int b) const override {
    const Material& first = materials_.at(static_cast<std::size_t>(a));
    const Material& second = materials_.at(static_cast<std::size_t>(b));
    ContactCoefficients result;
    const float friction = friction_on_ ? first.static_friction * second.static_friction : 0.0f;
    result.static_friction = friction;
    result.dynamic_friction = friction;
    result.restitution = restitution_on_ ? first.restitution * second.restitution : 0.0f;
    return result;
  }
  unsigned long long state_hash() const override {
    std::vector<BodyState> states;
    read_states(states);
    return hash_states(states);
  }
  void place_body(int index, vec2 position, vec2 velocity) override {
    cpBody* body = bodies_.at(static_cast<std::size_t>(index));
    cpBodySetPosition(body, cpv(position.x, position.y));
    cpBodySetAngle(body, 0.0);
    cpBodySetVelocity(body, cpv(velocity.x, velocity.y));
    cpBodySetAngularVelocity(body, 0.0);
  }

 private:
  void free_all() {
    // The space goes first (its teardown only wakes its bodies): removing shapes one at a time
    // filters every cached arbiter for each, quadratic in the body count (5 s for 10,000 boxes).
    cpSpaceFree(space_);
    for (cpConstraint* constraint : constraints_) cpConstraintFree(constraint);
    for (cpShape* shape : shapes_) cpShapeFree(shape);
    for (cpBody* body : bodies_) cpBodyFree(body);
  }

  cpSpace* space_;
  LabMethod method_;
  vec2 gravity_;
  std::vector<cpBody*> bodies_;
  std::vector<cpShape*> shapes_;
  std::vector<Material> materials_;
  std::vector<bool> dynamic_;
  std::vector<bool> rotates_;
  std::vector<cpConstraint*> constraints_;
  bool diverged_ = false;  // a body left the finite range: stepping stopped
  std::vector<LabJoint> joints_;
  bool friction_on_ = true;
  bool restitution_on_ = true;
};

}  // namespace

std::unique_ptr<LabSimulation> make_chipmunk_simulation(const World& initial,
                                                        const std::vector<LabJoint>& joints,
                                                        const LabMethod& method) {
  return std::make_unique<ChipmunkSimulation>(initial, joints, method);
}

}  // namespace impulse2d::lab

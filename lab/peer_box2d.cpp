/// @file peer_box2d.cpp
/// Box2D 2.4.1 as a lab peer (compiled only when libbox2d-dev is installed).
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lab/lab_peers.h"
#include "core/world.h"

namespace impulse2d::lab {
namespace {

b2Vec2 to_b2(vec2 v) { return b2Vec2(v.x, v.y); }

[[noreturn]] void unsupported(const LabJoint& joint, const std::string& what) {
  throw std::runtime_error(std::string(demos::joint_type_name(joint.spec.type)) + " joint " +
                           (joint.spec.origin.empty() ? "" : joint.spec.origin + " ") + "with " +
                           what + ": not supported by Box2D 2.4.1");
}

// The bodies and collide_connected of any joint definition.
template <class B2Def, class Source>
void attach(B2Def& def, b2Body* a, b2Body* b, const Source& source) {
  def.bodyA = a;
  def.bodyB = b;
  def.collideConnected = source.collide_connected;
}

// The local anchors of an anchored joint (the adapter's body origins are the centres of mass).
template <class B2Def, class Source>
void set_anchors(B2Def& def, const Source& source) {
  def.localAnchorA = to_b2(source.local_anchor_a);
  def.localAnchorB = to_b2(source.local_anchor_b);
}

/// Builds `joint` between `a` and `b` in `world`. Box2D 2.4.1's anchors are from the body's
/// origin, which the adapter puts at the centre of mass, so the local anchors carry over.
void create_box2d_joint(b2World& world, const LabJoint& joint, b2Body* a, b2Body* b) {
  const demos::JointSpec& spec = joint.spec;
  switch (spec.type) {
    case JointType::Revolute: {
      const RevoluteJointDef& source = spec.revolute;
      if (source.enable_spring && source.hertz > 0.0f) unsupported(joint, "a spring");
      b2RevoluteJointDef def;
      attach(def, a, b, source);
      set_anchors(def, source);
      def.referenceAngle = source.reference_angle;
      def.enableLimit = source.enable_limit;
      def.lowerAngle = source.lower_angle;
      def.upperAngle = source.upper_angle;
      def.enableMotor = source.enable_motor;
      def.motorSpeed = source.motor_speed;
      def.maxMotorTorque = source.max_motor_torque;
      world.CreateJoint(&def);
      return;
    }
    case JointType::Prismatic: {
      const PrismaticJointDef& source = spec.prismatic;
      if (source.enable_spring && source.hertz > 0.0f) unsupported(joint, "a spring");
      b2PrismaticJointDef def;
      attach(def, a, b, source);
      set_anchors(def, source);
      def.localAxisA = to_b2(source.local_axis_a);
      def.localAxisA.Normalize();
      def.referenceAngle = source.reference_angle;
      def.enableLimit = source.enable_limit;
      def.lowerTranslation = source.lower_translation;
      def.upperTranslation = source.upper_translation;
      def.enableMotor = source.enable_motor;
      def.motorSpeed = source.motor_speed;
      def.maxMotorForce = source.max_motor_force;
      world.CreateJoint(&def);
      return;
    }
    case JointType::Distance: {
      // Box2D 2.4.1 holds the length rigidly only when minLength == maxLength (or without
      // stiffness); a spring acts only when minLength < maxLength, between them.
      const DistanceJointDef& source = spec.distance;
      if (source.enable_motor) unsupported(joint, "a motor");
      b2DistanceJointDef def;
      attach(def, a, b, source);
      set_anchors(def, source);
      def.length = source.length;
      if (!source.enable_spring) {
        def.minLength = def.maxLength = source.length;
      } else {
        def.minLength = source.enable_limit ? source.min_length : 0.0f;
        def.maxLength = source.enable_limit ? source.max_length : FLT_MAX;
        if (source.hertz > 0.0f) {
          b2LinearStiffness(def.stiffness, def.damping, source.hertz, source.damping_ratio, a, b);
        }
      }
      world.CreateJoint(&def);
      return;
    }
    case JointType::Weld: {
      // 2.4.1's weld has an angular spring only.
      const WeldJointDef& source = spec.weld;
      if (source.linear_hertz > 0.0f) unsupported(joint, "a linear spring");
      b2WeldJointDef def;
      attach(def, a, b, source);
      set_anchors(def, source);
      def.referenceAngle = source.reference_angle;
      if (source.angular_hertz > 0.0f) {
        b2AngularStiffness(def.stiffness, def.damping, source.angular_hertz,
                           source.angular_damping_ratio, a, b);
      }
      world.CreateJoint(&def);
      return;
    }
    case JointType::Wheel: {
      const WheelJointDef& source = spec.wheel;
      b2WheelJointDef def;
      attach(def, a, b, source);
      set_anchors(def, source);
      def.localAxisA = to_b2(source.local_axis_a);
      def.localAxisA.Normalize();
      def.enableLimit = source.enable_limit;
      def.lowerTranslation = source.lower_translation;
      def.upperTranslation = source.upper_translation;
      def.enableMotor = source.enable_motor;
      def.motorSpeed = source.motor_speed;
      def.maxMotorTorque = source.max_motor_torque;
      def.stiffness = 0.0f;
      def.damping = 0.0f;
      if (source.enable_spring && source.hertz > 0.0f) {
        b2LinearStiffness(def.stiffness, def.damping, source.hertz, source.damping_ratio, a, b);
      }
      world.CreateJoint(&def);
      return;
    }
    case JointType::Motor: {
      const MotorJointDef& source = spec.motor;
      b2MotorJointDef def;
      attach(def, a, b, source);
      def.linearOffset = to_b2(source.linear_offset);
      def.angularOffset = source.angular_offset;
      def.maxForce = source.max_force;
      def.maxTorque = source.max_torque;
      def.correctionFactor = source.correction_factor;
      world.CreateJoint(&def);
      return;
    }
    case JointType::Mouse: {
      // 2.4.1's mouse joint grabs B where its target is at creation: create it at the anchor,
      // then move the target.
      const MouseJointDef& source = spec.mouse;
      b2MouseJointDef def;
      attach(def, a, b, source);
      def.target = b->GetWorldPoint(to_b2(source.local_anchor_b));
      def.maxForce = source.max_force;
      b2LinearStiffness(def.stiffness, def.damping, source.hertz, source.damping_ratio, a, b);
      static_cast<b2MouseJoint*>(world.CreateJoint(&def))->SetTarget(to_b2(source.target));
      return;
    }
  }
}

/// A chain link (a one-sided segment with ghost vertices) as Box2D 2.4.1's one-sided edge:
/// SetOneSided(v0, v1, v2, v3) collides on the RIGHT of v1 -> v2 with v0 before v1 and v3 after
/// v2, where impulse2d's link collides on the LEFT of point1 -> point2; so the edge runs
/// backwards: v1 = point2, v2 = point1, v0 = ghost2, v3 = ghost1. At an open chain's end
/// impulse2d's ghost is the end point itself (a free corner); Box2D needs a vertex there that
/// differs from the end (its smoothing normalises v1 - v0), so the link is extended straight on,
/// which a body that stays on the chain never meets.
void set_chain_link(b2EdgeShape& edge, const Segment& source) {
  const vec2 ahead = source.ghost2 == source.point2 ? 2.0f * source.point2 - source.point1 : source.ghost2;
  const vec2 behind = source.ghost1 == source.point1 ? 2.0f * source.point1 - source.point2 : source.ghost1;
  edge.SetOneSided(to_b2(ahead), to_b2(source.point2), to_b2(source.point1), to_b2(behind));
}

class Box2dSimulation : public LabSimulation {
 public:
  Box2dSimulation(const World& initial, const std::vector<LabJoint>& joints,
                  const LabMethod& method)
      : world_(b2Vec2(initial.settings().gravity.x, initial.settings().gravity.y)),
        method_(method),
        gravity_(initial.settings().gravity) {
    const WorldSettings& settings = initial.settings();
    world_.SetAllowSleeping(settings.enable_sleeping);
    world_.SetContinuousPhysics(settings.enable_continuous);
    for (const BodyId id : initial.body_ids()) {
      const BodyView body = initial.body(id);
      b2BodyDef def;
      def.type = body.type == BodyType::Static      ? b2_staticBody
                 : body.type == BodyType::Kinematic ? b2_kinematicBody
                                                    : b2_dynamicBody;
      def.position.Set(body.transform.position.x, body.transform.position.y);
      def.angle = body.angle;
      def.linearVelocity.Set(body.linear_velocity.x, body.linear_velocity.y);
      def.angularVelocity = body.angular_velocity;
      def.gravityScale = body.gravity_scale;
      def.linearDamping = body.linear_damping;
      def.angularDamping = body.angular_damping;
      def.fixedRotation = body.inverse_inertia == 0.0f;
      def.bullet = body.is_bullet && settings.enable_continuous;
      def.allowSleep = settings.enable_sleeping;
      if (body.shape_count > 0) {
        throw std::runtime_error("peer box2d: compound bodies (several shapes) are not copied to the peers");
      }
      b2Body* created = world_.CreateBody(&def);

      b2CircleShape circle;
      b2PolygonShape polygon;
      b2EdgeShape edge;
      b2FixtureDef fixture;
      switch (body.shape->type()) {
        case ShapeType::Circle:
          circle.m_radius = body.shape->circle().radius;
          fixture.shape = &circle;
          break;
        case ShapeType::Box:
          // Box2D rounds every polygon by b2_polygonRadius: shrink it by that skin so the
          // rounded outline has the scene's size (else every contact rests 2 skins apart).
          polygon.SetAsBox(body.shape->box().half_extents.x - b2_polygonRadius,
                           body.shape->box().half_extents.y - b2_polygonRadius);
          fixture.shape = &polygon;
          break;
        case ShapeType::Polygon: {
          b2Vec2 vertices[b2_maxPolygonVertices];
          const Polygon& source = body.shape->polygon();
          const int count = std::min(source.count, int{b2_maxPolygonVertices});
          for (int i = 0; i < count; ++i) {
            // Each edge moved inward by the skin: the vertex moves along the sum of its two edge
            // normals, scaled so both edges move by exactly b2_polygonRadius.
            const vec2 before = source.normals[static_cast<std::size_t>((i + count - 1) % count)];
            const vec2 after = source.normals[static_cast<std::size_t>(i)];
            const float scale = b2_polygonRadius / (1.0f + before.x * after.x + before.y * after.y);
            const vec2 vertex = source.vertices[static_cast<std::size_t>(i)];
            vertices[i].Set(vertex.x - scale * (before.x + after.x),
                            vertex.y - scale * (before.y + after.y));
          }
          polygon.Set(vertices, count);
          polygon.m_radius = b2_polygonRadius + source.rounding;  // the skin plus the rounding
          fixture.shape = &polygon;
          break;
        }
        case ShapeType::Segment: {
          const Segment& source = body.shape->segment();
          if (source.one_sided) {
            set_chain_link(edge, source);
          } else {
            edge.SetTwoSided(to_b2(source.point1), to_b2(source.point2));
          }
          fixture.shape = &edge;
          break;
        }
        case ShapeType::Capsule:
          throw std::runtime_error("peer box2d: Box2D 2.4.1 has no capsule shape");
      }
      fixture.density = body.type == BodyType::Dynamic ? body.material->density : 0.0f;
      fixture.friction = settings.enable_friction ? body.material->static_friction : 0.0f;
      fixture.restitution = settings.enable_restitution ? body.material->restitution : 0.0f;
      fixture.restitutionThreshold = settings.restitution_threshold;
      fixture.filter.categoryBits = static_cast<uint16>(body.collision_layers & 0xFFFFu);
      fixture.filter.maskBits = static_cast<uint16>(body.collision_layers & 0xFFFFu);
      created->CreateFixture(&fixture);
      bodies_.push_back(created);
      materials_.push_back(*body.material);
    }
    friction_on_ = settings.enable_friction;
    restitution_on_ = settings.enable_restitution;
    for (const LabJoint& joint : joints) {
      create_box2d_joint(world_, joint, bodies_.at(static_cast<std::size_t>(joint.body_a)),
                         bodies_.at(static_cast<std::size_t>(joint.body_b)));
    }
    joints_ = joints;
  }
  const std::vector<LabJoint>& joints() const override { return joints_; }

  void step() override {
    world_.Step(method_.time_step, method_.velocity_iterations, method_.position_iterations);
  }
  float time_step() const override { return method_.time_step; }
  vec2 gravity() const override { return gravity_; }
  int body_count() const override { return static_cast<int>(bodies_.size()); }
  void read_states(std::vector<BodyState>& states) const override {
    states.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const b2Body* body = bodies_[i];
      BodyState& state = states[i];
      state.position = {body->GetWorldCenter().x, body->GetWorldCenter().y};
      state.angle = body->GetAngle();
      state.velocity = {body->GetLinearVelocity().x, body->GetLinearVelocity().y};
      state.angular_velocity = body->GetAngularVelocity();
      state.mass = body->GetMass();
      state.inertia = body->IsFixedRotation() ? 0.0f : body->GetInertia();
      state.dynamic = body->GetType() == b2_dynamicBody;
    }
  }
  ContactCoefficients coefficients(int a, int b) const override {
    const Material& first = materials_.at(static_cast<std::size_t>(a));
    const Material& second = materials_.at(static_cast<std::size_t>(b));
    ContactCoefficients result;
    const float friction =
        friction_on_ ? std::sqrt(first.static_friction * second.static_friction) : 0.0f;
    result.static_friction = friction;
    result.dynamic_friction = friction;
    result.restitution = restitution_on_ ? std::max(first.restitution, second.restitution) : 0.0f;
    return result;
  }
  unsigned long long state_hash() const override {
    std::vector<BodyState> states;
    read_states(states);
    return hash_states(states);
  }
  void place_body(int index, vec2 position, vec2 velocity) override {
    b2Body* body = bodies_.at(static_cast<std::size_t>(index));
    body->SetTransform(b2Vec2(position.x, position.y), 0.0f);
    body->SetLinearVelocity(b2Vec2(velocity.x, velocity.y));
    body->SetAngularVelocity(0.0f);
  }

 private:
  b2World world_;
  LabMethod method_;
  vec2 gravity_;
  std::vector<b2Body*> bodies_;
  std::vector<Material> materials_;
  bool friction_on_ = true;
  bool restitution_on_ = true;
  std::vector<LabJoint> joints_;
};

}  // namespace

std::unique_ptr<LabSimulation> make_box2d_simulation(const World& initial,
                                                     const std::vector<LabJoint>& joints,
                                                     const LabMethod& method) {
  return std::make_unique<Box2dSimulation>(initial, joints, method);
}

}  // namespace impulse2d::lab

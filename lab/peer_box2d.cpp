/// @file peer_box2d.cpp
/// Box2D 2.4.1 as a lab peer (compiled only when libbox2d-dev is installed).
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>

#include "lab/lab_peers.h"
#include "core/world.h"

namespace impulse2d::lab {
namespace {

class Box2dSimulation : public LabSimulation {
 public:
  Box2dSimulation(const World& initial, const LabMethod& method)
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
      b2Body* created = world_.CreateBody(&def);

      b2CircleShape circle;
      b2PolygonShape polygon;
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
          fixture.shape = &polygon;
          break;
        }
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
  }

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
};

}  // namespace

std::unique_ptr<LabSimulation> make_box2d_simulation(const World& initial, const LabMethod& method) {
  return std::make_unique<Box2dSimulation>(initial, method);
}

}  // namespace impulse2d::lab

/// @file engine_simulation.cpp
#include "lab/engine_simulation.h"

#include <algorithm>

#include "core/material.h"
#include "scene/usage_error.h"

namespace impulse2d::lab {

void read_world_states(const World& world, const std::vector<BodyId>& bodies,
                       std::vector<BodyState>& states) {
  states.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const BodyView body = world.body(bodies[i]);
    BodyState& state = states[i];
    state.position = body.transform.position;
    state.angle = body.angle;
    state.velocity = body.linear_velocity;
    state.angular_velocity = body.angular_velocity;
    state.mass = body.mass;
    state.inertia = body.inverse_inertia > 0.0f ? body.inertia : 0.0f;
    state.dynamic = body.type == BodyType::Dynamic;
  }
}

vec2 world_point(const BodyState& state, vec2 local) {
  const float c = std::cos(state.angle), s = std::sin(state.angle);
  return {state.position.x + c * local.x - s * local.y, state.position.y + s * local.x + c * local.y};
}

std::vector<LabJoint> scene_joints(const demos::Scene& scene, const World& world) {
  const std::vector<BodyId> bodies = world.body_ids();
  std::vector<LabJoint> joints;
  for (const demos::JointSpec& spec : scene.joints) {
    if (spec.body_a < 0 || spec.body_b < 0 || static_cast<std::size_t>(spec.body_a) >= bodies.size() ||
        static_cast<std::size_t>(spec.body_b) >= bodies.size()) {
      throw demos::UsageError(scene.name + ": " + spec.origin + ": a body of the joint is not in the world");
    }
    LabJoint joint;
    joint.spec = spec;
    joint.body_a = spec.body_a;
    joint.body_b = spec.body_b;
    const BodyView a = world.body(bodies[static_cast<std::size_t>(spec.body_a)]);
    const BodyView b = world.body(bodies[static_cast<std::size_t>(spec.body_b)]);
    // As demos::create_scene_joint: world anchors and axis into each body's frame, the relative
    // angle now as joint angle 0, a distance joint's length from its anchors when not given.
    joint.local_anchor_a = a.transform.apply_inverse(spec.anchor_a);
    joint.local_anchor_b = b.transform.apply_inverse(spec.anchor_b);
    const float axis_length = glm::length(spec.axis);
    const vec2 axis = axis_length > 0.0f ? spec.axis / axis_length : vec2(0.0f, 0.0f);
    const vec2 local_axis = a.transform.rotation.inverse_rotate(axis);
    const float relative_angle = b.angle - a.angle;
    demos::JointSpec& def = joint.spec;
    def.revolute.local_anchor_a = def.prismatic.local_anchor_a = def.distance.local_anchor_a =
        def.weld.local_anchor_a = def.wheel.local_anchor_a = joint.local_anchor_a;
    def.revolute.local_anchor_b = def.prismatic.local_anchor_b = def.distance.local_anchor_b =
        def.weld.local_anchor_b = def.wheel.local_anchor_b = def.mouse.local_anchor_b =
            joint.local_anchor_b;
    if (spec.type == JointType::Mouse && spec.anchor_b_is_center) {
      def.mouse.local_anchor_b = joint.local_anchor_b = vec2(0.0f, 0.0f);
    }
    def.prismatic.local_axis_a = def.wheel.local_axis_a = local_axis;
    def.revolute.reference_angle = def.prismatic.reference_angle = def.weld.reference_angle =
        relative_angle;
    if (!spec.has_length) {
      def.distance.length = std::max(glm::length(spec.anchor_b - spec.anchor_a), 0.005f);
    }
    def.revolute.collide_connected = def.prismatic.collide_connected =
        def.distance.collide_connected = def.weld.collide_connected =
            def.wheel.collide_connected = def.motor.collide_connected =
                def.mouse.collide_connected = spec.collide_connected;
    joints.push_back(joint);
  }
  return joints;
}

ContactCoefficients world_coefficients(const World& world, BodyId a, BodyId b) {
  const WorldSettings& settings = world.settings();
  const Material& first = *world.body(a).material;
  const Material& second = *world.body(b).material;
  ContactCoefficients result;
  result.static_friction =
      mix_friction(first.static_friction, second.static_friction, settings.friction_mixing);
  result.dynamic_friction =
      mix_friction(first.dynamic_friction, second.dynamic_friction, settings.friction_mixing);
  result.restitution =
      mix_restitution(first.restitution, second.restitution, settings.restitution_mixing);
  return result;
}

EngineSimulation::EngineSimulation(const demos::Scene& scene, const LabMethod& method)
    : EngineSimulation(scene, method, demos::Params(scene.params)) {}

EngineSimulation::EngineSimulation(const demos::Scene& scene, const LabMethod& method,
                                   const demos::Params& params)
    : scene_(apply_method(method, scene)) {
  run_ = std::make_unique<demos::SceneRun>(scene_, params);
  bodies_ = run_->world().body_ids();
  joints_ = scene_joints(scene_, run_->world());
}

void EngineSimulation::step() {
  run_->step();
  if (!run_->world().diverged_bodies().empty()) diverged_ = true;
}

float EngineSimulation::time_step() const { return run_->world().settings().time_step; }

vec2 EngineSimulation::gravity() const { return run_->world().settings().gravity; }

int EngineSimulation::body_count() const { return static_cast<int>(bodies_.size()); }

void EngineSimulation::read_states(std::vector<BodyState>& states) const {
  read_world_states(run_->world(), bodies_, states);
}

ContactCoefficients EngineSimulation::coefficients(int a, int b) const {
  return world_coefficients(run_->world(), bodies_.at(static_cast<std::size_t>(a)),
                            bodies_.at(static_cast<std::size_t>(b)));
}

unsigned long long EngineSimulation::state_hash() const { return run_->world().state_hash(); }

}  // namespace impulse2d::lab

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
    joint.body_a = spec.body_a;
    joint.body_b = spec.body_b;
    const BodyView a = world.body(bodies[static_cast<std::size_t>(spec.body_a)]);
    const BodyView b = world.body(bodies[static_cast<std::size_t>(spec.body_b)]);
    joint.spec = demos::complete_joint_spec(spec, a, b);  // as the scene run created it
    joint.local_anchor_a = joint.spec.revolute.local_anchor_a;  // every anchored type has the same
    joint.local_anchor_b = spec.type == JointType::Mouse ? joint.spec.mouse.local_anchor_b
                                                          : joint.spec.revolute.local_anchor_b;
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

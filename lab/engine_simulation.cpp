/// @file engine_simulation.cpp
#include "lab/engine_simulation.h"

#include "core/material.h"

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

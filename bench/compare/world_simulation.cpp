/// @file world_simulation.cpp
#include "bench/compare/world_simulation.h"

#include "lab/engine_simulation.h"

namespace impulse2d::compare {

WorldSimulation::WorldSimulation(const CompareScene& scene, const WorldSettings& settings)
    : world_(settings) {
  bodies_.reserve(scene.bodies.size());
  for (const BodySpec& spec : scene.bodies) bodies_.push_back(world_.create_body(spec.def, spec.shape));
}

void WorldSimulation::read_states(std::vector<lab::BodyState>& states) const {
  lab::read_world_states(world_, bodies_, states);
}

lab::ContactCoefficients WorldSimulation::coefficients(int a, int b) const {
  return lab::world_coefficients(world_, bodies_.at(static_cast<std::size_t>(a)),
                                 bodies_.at(static_cast<std::size_t>(b)));
}

void WorldSimulation::place_body(int index, vec2 position, vec2 velocity) {
  const BodyId id = bodies_.at(static_cast<std::size_t>(index));
  world_.set_transform(id, position, 0.0f);
  world_.set_linear_velocity(id, velocity);
  world_.set_angular_velocity(id, 0.0f);
}

}  // namespace impulse2d::compare

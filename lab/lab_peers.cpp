/// @file lab_peers.cpp
#include "lab/lab_peers.h"

#include <cstring>
#include <string>
#include <stdexcept>

#include "lab/engine_simulation.h"

namespace impulse2d::lab {

bool engine_available(Engine engine) {
  switch (engine) {
    case Engine::Impulse2d: return true;
    case Engine::Box2d:
#ifdef IMPULSE2D_HAVE_BOX2D
      return true;
#else
      return false;
#endif
    case Engine::Chipmunk:
#ifdef IMPULSE2D_HAVE_CHIPMUNK
      return true;
#else
      return false;
#endif
  }
  return false;
}

std::string engine_note(Engine engine) {
  if (engine == Engine::Impulse2d) return "";
  if (!engine_available(engine)) {
    return std::string(engine == Engine::Box2d ? "libbox2d-dev" : "libchipmunk-dev") +
           " was not found when the project was configured: peer " + engine_name(engine) +
           " skipped (scripts/setup.sh installs it; then re-run cmake)";
  }
  if (engine == Engine::Chipmunk) {
    return "Chipmunk 7.0.3 as Debian ships it is a debug build (runtime assertions on), so its "
           "times are pessimistic";
  }
  return "";
}

std::unique_ptr<LabSimulation> make_simulation(const demos::Scene& scene, const LabMethod& method) {
  auto engine = std::make_unique<EngineSimulation>(scene, method);
  if (method.engine == Engine::Impulse2d) return engine;
  if (engine_available(method.engine) &&
      static_cast<std::size_t>(engine->world().joint_count()) != engine->joints().size()) {
    // A built-in scene's code made joints the peer cannot see: refuse rather than drop them.
    throw std::runtime_error(std::string(scene.name) + ": " +
                             std::to_string(engine->world().joint_count() -
                                            static_cast<int>(engine->joints().size())) +
                             " joints made by the scene's code (not its \"joints\"): not supported by " +
                             (method.engine == Engine::Box2d ? "Box2D 2.4.1" : "Chipmunk 7.0.3"));
  }
  switch (method.engine) {
    case Engine::Impulse2d: return engine;
    case Engine::Box2d:
#ifdef IMPULSE2D_HAVE_BOX2D
      return make_box2d_simulation(engine->world(), engine->joints(), method);
#else
      break;
#endif
    case Engine::Chipmunk:
#ifdef IMPULSE2D_HAVE_CHIPMUNK
      return make_chipmunk_simulation(engine->world(), engine->joints(), method);
#else
      break;
#endif
  }
  throw std::runtime_error(engine_note(method.engine));
}

unsigned long long hash_states(const std::vector<BodyState>& states) {
  unsigned long long hash = 1469598103934665603ull;
  const auto mix = [&hash](float value) {
    unsigned int bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    for (int byte = 0; byte < 4; ++byte) {
      hash ^= (bits >> (8 * byte)) & 0xFFu;
      hash *= 1099511628211ull;
    }
  };
  for (const BodyState& state : states) {
    mix(state.position.x);
    mix(state.position.y);
    mix(state.angle);
    mix(state.velocity.x);
    mix(state.velocity.y);
    mix(state.angular_velocity);
  }
  return hash;
}

}  // namespace impulse2d::lab

#pragma once
/// @file world_simulation.h
/// impulse2d stepping a bench_compare scene directly (no scene run around the world), as a
/// `LabSimulation` beside the peers.

#include <vector>

#include "bench/compare/compare_scene.h"
#include "lab/lab_simulation.h"
#include "core/world.h"

namespace impulse2d::compare {

/// A world built from a scene's bodies with the given settings.
class WorldSimulation : public lab::LabSimulation {
 public:
  /// Creates every body of `scene` in a world with `settings`.
  WorldSimulation(const CompareScene& scene, const WorldSettings& settings);
  void step() override { world_.step(); }
  float time_step() const override { return world_.settings().time_step; }
  vec2 gravity() const override { return world_.settings().gravity; }
  int body_count() const override { return static_cast<int>(bodies_.size()); }
  void read_states(std::vector<lab::BodyState>& states) const override;
  lab::ContactCoefficients coefficients(int a, int b) const override;
  unsigned long long state_hash() const override { return world_.state_hash(); }
  bool diverged() const override { return !world_.diverged_bodies().empty(); }
  void place_body(int index, vec2 position, vec2 velocity) override;

 private:
  World world_;
  std::vector<BodyId> bodies_;  // creation index -> handle
};

}  // namespace impulse2d::compare

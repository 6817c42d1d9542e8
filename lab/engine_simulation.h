#pragma once
/// @file engine_simulation.h
/// impulse2d itself as a `LabSimulation`: a scene run (demos::SceneRun) under one method.

#include <memory>

#include "lab/lab_method.h"
#include "lab/lab_simulation.h"
#include "scene/scene_run.h"

namespace impulse2d::lab {

/// Fills `states` with the state of `bodies` of `world`, in that order (the buffer is reused).
void read_world_states(const World& world, const std::vector<BodyId>& bodies,
                       std::vector<BodyState>& states);

/// The coefficients `world`'s mixing rules give a contact between bodies `a` and `b`.
ContactCoefficients world_coefficients(const World& world, BodyId a, BodyId b);

/// The joints of `scene` (its `joints`, created right after its bodies) completed from the
/// bodies of `world` before its first step, as `demos::create_scene_joint` completes them.
/// Joints a built-in scene's code creates are not among them (the world's `joint_count()`
/// then exceeds the list's size).
std::vector<LabJoint> scene_joints(const demos::Scene& scene, const World& world);

/// A scene stepped by impulse2d with a method's settings.
class EngineSimulation : public LabSimulation {
 public:
  /// Builds `scene` with `method` applied and the scene's default parameters (throws as
  /// `demos::SceneRun` does).
  EngineSimulation(const demos::Scene& scene, const LabMethod& method);
  /// The same with the given parameters.
  EngineSimulation(const demos::Scene& scene, const LabMethod& method, const demos::Params& params);
  void step() override;
  float time_step() const override;
  vec2 gravity() const override;
  int body_count() const override;
  void read_states(std::vector<BodyState>& states) const override;
  ContactCoefficients coefficients(int a, int b) const override;
  unsigned long long state_hash() const override;
  bool diverged() const override { return diverged_; }
  const std::vector<LabJoint>& joints() const override { return joints_; }
  /// The world being stepped.
  const World& world() const { return run_->world(); }

 private:
  demos::Scene scene_;  // owned: the run keeps a reference to it
  std::unique_ptr<demos::SceneRun> run_;
  std::vector<BodyId> bodies_;  // creation index -> handle
  bool diverged_ = false;       // some step reported non-finite bodies
  std::vector<LabJoint> joints_;  // the scene's joints as built
};

}  // namespace impulse2d::lab

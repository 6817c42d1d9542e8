#pragma once
/// @file golden_run.h
/// One run of a golden's scene: the scene (with a variant applied) built with the golden's
/// parameters and stepped, and what the golden records about its world (body poses and
/// whole-world physical quantities).

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_run.h"
#include "golden/body_drift.h"
#include "golden/noise_envelope.h"
#include "golden/scenes/golden_catalog.h"

namespace impulse2d::golden {

/// Changes a copy of a scene before it runs, e.g. a solver setting for sensitivity tests.
using SceneVariant = std::function<void(demos::Scene&)>;

/// A golden's scene built and ready to step; owns the scene copy its run refers to.
class GoldenRun {
 public:
  /// Copies `spec`'s built-in scene (or loads `spec.scene_file`), applies `variant` (when
  /// given), sets `spec.params` over the scene's defaults and builds the world. Throws
  /// `GoldenError` for an unknown scene, and whatever loading or the scene's run throws.
  explicit GoldenRun(const GoldenSpec& spec, const SceneVariant& variant = nullptr);

  /// The scene as run (variant applied).
  const demos::Scene& scene() const { return *scene_; }
  /// The run: world, step count, script overlays.
  demos::SceneRun& run() { return *run_; }
  /// The world as of `run().step_count()` steps.
  const World& world() const { return run_->world(); }
  /// Takes one step.
  void step() { run_->step(); }

 private:
  std::unique_ptr<demos::Scene> scene_;  // heap: the run keeps a reference to it
  std::unique_ptr<demos::SceneRun> run_;
};

/// Every body's pose, in slot order. Bodies are named "body <slot>", with the slot's
/// generation when it was reused ("body 7 (generation 2)"), so a body created in a removed
/// body's slot is never compared with its predecessor.
std::vector<BodyPose> body_poses(const World& world);

/// The world's energy (as `impulse2d trace` reports it), linear and angular momentum of its
/// dynamic bodies, and contact count, stamped with the world's step count.
PhysicsSample sample_physics(const World& world);

}  // namespace impulse2d::golden

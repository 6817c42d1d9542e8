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

/// Continues a golden's freshly built run before its first step, e.g. from a state saved by
/// `impulse2d trace --save-state` (`impulse2d golden frame --load-state`), to at most
/// `frame_step` (the golden's step); throws when it cannot.
using RunStart = std::function<void(demos::SceneRun& run, std::int64_t frame_step)>;

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
  /// Takes one step and gives the bodies it created their creation indices. Step only
  /// through this (not `run().step()`), or bodies created in between are numbered late.
  void step();

  /// Every living body's pose, named by creation order, not by world slot, so runs whose
  /// removals free slots at different steps (a chaotic scene under rounding noise) still
  /// name the same body alike: the scene file's name and creation index
  /// ("ball (#3)"), else "body #12". The scene's bodies and its spawn events' bodies take
  /// the scene run's creation indices; bodies a scene script creates follow them, in step
  /// order, those of one step ordered by position (x, then y).
  std::vector<BodyPose> body_poses() const;

 private:
  /// Gives bodies created since the last call their creation indices.
  void track_new_bodies();

  std::unique_ptr<demos::Scene> scene_;  // heap: the run keeps a reference to it
  std::unique_ptr<demos::SceneRun> run_;
  /// Per world slot: the generation last seen there and its body's creation index.
  std::vector<std::pair<std::uint32_t, int>> creation_by_slot_;
  int next_script_index_ = 0;  ///< the next creation index of a script's body
};

/// Every body's pose, in slot order, named by slot ("body <slot>", with the slot's
/// generation when it was reused: "body 7 (generation 2)"): the names of sidecars written
/// before issue 29, which are judged with these names (`is_slot_named`).
std::vector<BodyPose> body_poses(const World& world);

/// The world's energy (as `impulse2d trace` reports it), linear and angular momentum of its
/// dynamic bodies, and contact count, stamped with the world's step count.
PhysicsSample sample_physics(const World& world);

}  // namespace impulse2d::golden

#pragma once
/// @file scene_run.h
/// One run of a scene: the world built under the scene's model, stepped with its scripted
/// events and per-step script.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/world.h"
#include "demos/scene.h"

namespace impulse2d::demos {

/// Builds a scene's world and steps it.
class SceneRun {
 public:
  /// Creates the world with the scene's settings with its model applied (`apply_model`),
  /// builds it, checks the shape kinds against the model, and checks every event (button
  /// names, body indices that cannot exist). Throws `UsageError` for anything the user can
  /// fix (model, events) and `Error` when the builder gives the core bad input.
  SceneRun(const Scene& scene, const Params& params);

  /// The world as of `step_count()` steps.
  const World& world() const { return world_; }
  /// Steps taken so far.
  std::int64_t step_count() const { return world_.step_count(); }
  /// The scene being run.
  const Scene& scene() const { return scene_; }
  /// The parameters of this run.
  const Params& params() const { return params_; }

  /// Applies the events of step `step_count()`, runs the script's `before_step`, takes one
  /// world step and checks the shape kinds of any new body. Throws `UsageError` naming the
  /// event when it refers to a body that was removed.
  void step();

  /// Where a following camera looks now: the followed body's position, or nothing when the
  /// scene's camera does not follow or the body does not exist (yet).
  std::optional<vec2> followed_position() const;

  /// A drawing callback for `render::FrameOptions::extra_overlays`: the scene script's own
  /// overlays (if it has any), drawn when the frame has any overlay on besides shapes.
  /// Valid while this run lives.
  std::function<void(DebugDraw&, const DebugDrawOptions&)> script_overlays() const;

 private:
  void apply_event(const SceneEvent& event);
  BodyId event_body(const SceneEvent& event) const;

  const Scene& scene_;
  Params params_;
  World world_;
  std::unique_ptr<StepScript> script_;
  std::vector<const SceneEvent*> events_;  // sorted by step, stable for equal steps
  std::size_t next_event_ = 0;
  std::vector<BodyId> created_;  // creation index -> handle
};

}  // namespace impulse2d::demos

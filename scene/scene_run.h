#pragma once
/// @file scene_run.h
/// One run of a scene: the world built under the scene's model, stepped with its scripted
/// events and per-step script.

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/world.h"
#include "scene/scene.h"

namespace impulse2d::demos {

/// A body whose state became non-finite in a step (the world restored and stopped it).
struct Divergence {
  std::int64_t step = 0;  ///< the step it diverged in (1 = the first step)
  int body = -1;          ///< creation index (the scene's bodies in order, then spawned ones)
  std::string name;       ///< its name in the scene file, or empty
};

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

  /// Applies the events of step `step_count()` and the forces of the force events whose
  /// window covers it, runs the script's `before_step`, takes one
  /// world step, checks the shape kinds of any new body and records diverged bodies. Throws
  /// `UsageError` naming the event when it refers to a body that was removed, and
  /// `Interrupted` when SIGINT, SIGTERM or SIGHUP arrived.
  void step();

  /// The scene script's state after the steps taken so far (`StepScript::save_state`), or
  /// nothing when the scene has no script. Saved beside `world().save_snapshot()`.
  std::vector<std::uint8_t> save_script_state() const;

  /// Continues this run from `snapshot` and `script_state` (`World::save_snapshot` and
  /// `save_script_state` of a run of the same scene and parameters at the same step): the
  /// world takes its state, a fresh script takes the script's, and the scene's events before
  /// its step are taken as done. Throws `UsageError` when the run could not continue from it
  /// exactly: events before that step that leave state outside the world and the script
  /// (spawns, removals, joints, mouse targets, forces still acting; button presses are the
  /// script's state). Throws `Error` for a snapshot the core refuses or script bytes the script
  /// refuses (script state without a script, or none with one). Either way the run keeps
  /// its state.
  void restore_snapshot(const std::vector<std::uint8_t>& snapshot,
                        const std::vector<std::uint8_t>& script_state);
  /// True once `restore_snapshot` gave this run a saved state: its world is then not the one
  /// the scene starts from (a camera fitted to the scene must use a fresh run).
  bool restored() const { return restored_; }

  /// With `strict`, `step` throws `std::runtime_error` naming the first body that diverges
  /// (the command line's `--strict`); without, divergences are only recorded.
  void set_strict(bool strict) { strict_ = strict; }
  /// Every body that diverged so far, in step order.
  const std::vector<Divergence>& divergences() const { return divergences_; }
  /// Creation indices that can exist in this run: the built bodies plus the spawn events.
  int bodies_in_run() const { return bodies_in_run_; }

  /// The world slot of the body of creation index `creation_index` (the scene's bodies in
  /// order, then spawned ones), or nothing while it does not exist (not spawned yet, removed).
  std::optional<std::uint32_t> slot_of(int creation_index) const;

  /// Names for the body-ids overlay, by world slot: the scene file's name of the body in that
  /// slot, or empty (the overlay then shows the slot index). Valid while this run lives.
  std::function<std::string(std::uint32_t slot)> body_labels() const;

  /// The living joint named `name` in the scene (its `joints` or a create_joint event), or
  /// nothing (not created yet, destroyed, or destroyed with one of its bodies).
  std::optional<JointId> joint_named(const std::string& name) const;

  /// Where a following camera looks now: the followed body's position, or nothing when the
  /// scene's camera does not follow or the body does not exist (yet).
  std::optional<vec2> followed_position() const;

  /// A drawing callback for `render::FrameOptions::extra_overlays`: the scene script's own
  /// overlays (if it has any), drawn when the frame has any overlay on besides shapes.
  /// Valid while this run lives.
  std::function<void(DebugDraw&, const DebugDrawOptions&)> script_overlays() const;

 private:
  void apply_event(const SceneEvent& event);
  // Throws `UsageError` naming the event when its body, of `type`, is not dynamic (an impulse
  // or a force would silently do nothing).
  void check_movable(const SceneEvent& event, BodyType type) const;
  // Applies every force event whose window covers `step` (and forgets the finished ones).
  void apply_forces(std::int64_t step);

  // A force event in its window: it acts before each step until `end` (exclusive), at
  // `local_point` in its body's frame (the centre of mass when the event names no point).
  struct ActiveForce {
    const SceneEvent* event = nullptr;
    std::int64_t end = 0;
    vec2 local_point{0.0f, 0.0f};
  };
  void verify_model() const;  // verify_shape_kinds, naming the scene file
  BodyId event_body(const SceneEvent& event) const;
  // Creates a scene joint (`origin` names it in messages); throws `UsageError` when a body
  // does not exist (yet, or any more) or the core refuses the definition.
  void create_joint(const JointSpec& spec, std::int64_t step);
  // The living joint an event names; throws `UsageError` naming the event otherwise.
  JointId event_joint(const SceneEvent& event) const;

  const Scene& scene_;
  Params params_;
  World world_;
  std::unique_ptr<StepScript> script_;
  std::vector<const SceneEvent*> events_;  // sorted by step, stable for equal steps
  std::size_t next_event_ = 0;
  std::vector<ActiveForce> forces_;  // force events in their window, in application order
  std::vector<BodyId> created_;  // creation index -> handle
  std::map<std::string, JointId> joints_;  // joint name -> handle (named joints only)
  std::vector<Divergence> divergences_;
  int bodies_in_run_ = 0;
  bool strict_ = false;
  bool restored_ = false;
};

/// "body 3 (\"ball\") diverged in step 120 (its state became non-finite; ...)" for messages.
std::string describe_divergence(const Scene& scene, const Divergence& divergence);

}  // namespace impulse2d::demos

#pragma once
/// @file step_script.h
/// A scene's per-step behaviour written in C++: bodies raining in, a controller reading
/// buttons. Scripted events from data (`SceneEvent`) are applied by the run itself.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/body.h"

namespace impulse2d {
class World;
class DebugDraw;
struct DebugDrawOptions;
}

namespace impulse2d::demos {

/// Called by a `SceneRun` around every step. One instance lives for one run.
///
/// A script's state between steps (counters, random generators, handles, a controller) is
/// saved with the world (`save_state`) and taken back by a fresh instance (`restore_state`),
/// so `--load-state` continues a scripted run bit for bit as the run that saved it.
class StepScript {
 public:
  virtual ~StepScript() = default;
  /// Called just before step `step` is taken, after that step's scripted events.
  virtual void before_step(World& world, std::int64_t step) = 0;
  /// The script's state after the steps taken so far, as bytes of its own versioned layout
  /// (scene/script_state.h). A script with no state of its own writes only its version.
  virtual std::vector<std::uint8_t> save_state() const = 0;
  /// Takes back the state `save_state` wrote, into a script just made for the same scene and
  /// parameters that has not stepped, with `world` already restored to the same moment (the
  /// script may re-install what the world does not save, e.g. its contact filter). Throws
  /// `Error` saying what is wrong for bytes of another version, truncated or out of range, or
  /// naming bodies `world` does not hold; `world` is then not to be used by the run.
  virtual void restore_state(World& world, const std::vector<std::uint8_t>& bytes) = 0;
  /// The buttons this scene reacts to; a `Button` event naming another one is rejected
  /// before the run starts. None by default.
  virtual std::vector<std::string> buttons() const { return {}; }
  /// A button declared by `buttons()` was pressed (`pressed`) or released, just before the
  /// next step. Called only for declared buttons, so scenes without buttons need not
  /// override it.
  virtual void button(World& world, const std::string& name, bool pressed) {
    (void)world;
    (void)name;
    (void)pressed;
  }
  /// The body a following camera (`CameraSpec::Mode::Follow`) should keep centred, when the
  /// script made it (e.g. the player's character); none by default.
  virtual std::optional<BodyId> followed_body() const { return std::nullopt; }
  /// Draws the script's own overlays over the world's (e.g. a character's ground normal,
  /// timers and jumps left), in world coordinates, with the frame's palette and scales.
  /// Nothing by default.
  virtual void draw(const World& world, DebugDraw& draw, const DebugDrawOptions& options) const {
    (void)world;
    (void)draw;
    (void)options;
  }
};

}  // namespace impulse2d::demos

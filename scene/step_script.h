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
class StepScript {
 public:
  virtual ~StepScript() = default;
  /// Called just before step `step` is taken, after that step's scripted events.
  virtual void before_step(World& world, std::int64_t step) = 0;
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

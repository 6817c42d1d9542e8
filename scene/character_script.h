#pragma once
/// @file character_script.h
/// A scene script that plays a platformer character (gameplay/character.h) from button events:
/// `left`, `right`, `jump`, `down`. Used by the built-in `platformer` scene and by JSON scene
/// files with a `character` object.

#include <optional>
#include <string>
#include <vector>

#include "gameplay/character.h"
#include "gameplay/one_way_platform.h"
#include "scene/step_script.h"

namespace impulse2d::demos {

/// `BodyDef::user_data` of the bodies the character treats as one-way platforms (solid from
/// above, passable from below, dropped through with down + jump).
inline constexpr std::uint64_t one_way_platform_tag = 1;

/// Creates the character before the first step, turns the buttons into its input each step,
/// and makes every body tagged `one_way_platform_tag` a one-way platform. A following camera
/// follows the character; its overlays are drawn with the world's.
class CharacterScript : public StepScript {
 public:
  /// A script for a character made from `def` (its position is where it starts).
  explicit CharacterScript(CharacterDef def) : def_(std::move(def)) {}

  /// `left`, `right`, `jump`, `down`.
  std::vector<std::string> buttons() const override;
  /// Holds or releases one of the four buttons.
  void button(World& world, const std::string& name, bool pressed) override;
  /// Creates the character on the first call, then updates it from the buttons held.
  void before_step(World& world, std::int64_t step) override;
  /// The buttons held and, once it exists, the character: its one-way platforms, its body and
  /// its controller state.
  std::vector<std::uint8_t> save_state() const override;
  /// Takes back what `save_state` wrote and re-installs the one-way platforms' contact filter.
  void restore_state(World& world, const std::vector<std::uint8_t>& bytes) override;
  /// The character's body once it exists.
  std::optional<BodyId> followed_body() const override;
  /// The character's ground normal, timers and jumps left, labelled in the palette's colour.
  void draw(const World& world, DebugDraw& draw, const DebugDrawOptions& options) const override;

 private:
  CharacterDef def_;
  OneWayPlatforms one_way_;
  std::optional<Character> character_;
  bool left_ = false, right_ = false, jump_ = false, down_ = false;
};

}  // namespace impulse2d::demos

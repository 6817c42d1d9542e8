#pragma once
/// @file character.h
/// A platformer character on the engine: a dynamic, non-rotating box driven each fixed step by
/// a `CharacterInput`. The controller reads the world's persistent contacts (ground, walls,
/// ceilings, steep slopes) and sets the body's velocity and gravity scale before the step; the
/// solver does the rest. The jump follows the blog seed: v = sqrt(2 |g| h), gravity scale 0.5
/// while the button is held and the body rises, coyote time, jump buffering, extra jumps and
/// wall jumps.
///
/// Per fixed step, in this order: move kinematic platforms (set their velocities), call
/// `Character::update(world, input)`, then `world.step()`.

#include "core/body.h"
#include "gameplay/character_input.h"
#include "core/debug_draw.h"
#include "core/material.h"
#include "core/world.h"

#include <cstdint>

namespace impulse2d {

class OneWayPlatforms;

/// Whole steps in a window of `seconds` at `time_step` seconds per step: the largest n with
/// n * time_step <= seconds (a relative 1e-3 of a step absorbs float rounding, so 0.1 s at
/// 1/60 s is 6 steps). Throws `Error` unless seconds >= 0 and time_step > 0.
int window_steps(float seconds, float time_step);

/// Tuning of a character. Lengths in metres, speeds in m/s, times in seconds, angles in radians.
struct CharacterSettings {
  /// Steepest walkable ground: a contact is ground when n . up >= cos(max_slope).
  float max_slope = 0.87266463f;  // 50 degrees
  /// A contact whose normal lies within this angle of horizontal is a wall.
  float wall_angle = 0.17453293f;  // 10 degrees

  float max_speed = 6.0f;               ///< m/s along the ground (and in the air) at full input
  float ground_acceleration = 60.0f;    ///< m/s^2 towards the input speed on the ground
  float ground_deceleration = 80.0f;    ///< m/s^2 when stopping or turning on the ground
  float air_acceleration = 30.0f;       ///< m/s^2 of air control (towards the input speed)
  /// Ground friction (the contact's mixed static coefficient) at and above which the full ground
  /// acceleration and deceleration apply; on slipperier ground both scale by mu / this.
  float full_traction_friction = 0.5f;

  /// Metres: apex of a jump whose gravity scale stays 1 (button released at once):
  /// v = sqrt(2 |g| h). Held through the rise, the apex is h / held_gravity_scale.
  float jump_height = 1.2f;
  /// Gravity scale while the button is held and the body rises after a jump (1 disables
  /// variable jump height). Released once, the scale stays 1 until the next jump.
  float held_gravity_scale = 0.5f;
  /// Seconds after the last grounded step during which a jump still counts as from the ground.
  float coyote_time = 0.1f;
  /// Seconds a press is remembered: a press this long before landing jumps on landing.
  float jump_buffer_time = 0.1f;
  /// Jumps allowed in the air (1 = double jump); refilled on landing.
  int extra_jumps = 1;

  float wall_slide_speed = 2.0f;  ///< m/s: fastest fall while pressing into a wall
  /// m/s: velocity of a wall jump: x away from the wall, y up.
  vec2 wall_jump_velocity{6.0f, 8.0f};
  /// Seconds after a wall jump during which the horizontal input is ignored.
  float wall_jump_lock_time = 0.15f;

  /// Metres: a wall contact whose top is at most this far above the feet is a step (or the
  /// seam between two grounds): a grounded character walking into it is lifted onto it.
  float max_step_height = 0.05f;
  /// Metres below its feet that a character which was on the ground looks for walkable ground
  /// to stay on (crests, the top of a downhill slope, small steps) instead of flying off.
  float snap_distance = 0.2f;
};

/// Throws `Error` naming the field unless every setting is finite and in range.
void validate_character_settings(const CharacterSettings& settings);

/// Everything needed to create a character.
struct CharacterDef {
  vec2 position{0.0f, 0.0f};          ///< centre of the box, metres
  vec2 half_extents{0.3f, 0.5f};      ///< half width and half height, metres
  /// Restitution 0 so landings do not bounce; the friction acts on steep slopes and walls.
  Material material{"Character", 1.0f, 0.0f, 0.6f, 0.4f};
  std::uint32_t collision_layers = 1;  ///< as `BodyDef::collision_layers`
  std::uint64_t user_data = 0;        ///< as `BodyDef::user_data`
  CharacterSettings settings;         ///< tuning
};

/// What the character did in its last update.
enum class CharacterAction : std::uint8_t {
  None,         ///< no jump
  GroundJump,   ///< jumped off the ground
  CoyoteJump,   ///< jumped within the coyote window after leaving the ground
  AirJump,      ///< used an extra jump
  WallJump,     ///< jumped off a wall
  DropThrough,  ///< dropped through the one-way platform it stood on
};

/// Where the character was in its last update.
enum class CharacterSupport : std::uint8_t {
  Air,          ///< nothing under it
  Ground,       ///< on walkable ground (from a contact or from ground snapping)
  WallSlide,    ///< in the air, pressing into a wall
  SteepSlope,   ///< on ground steeper than `max_slope`: it slides
};

/// A surface the character touches, as seen from the character.
struct CharacterSurface {
  BodyId body;                       ///< the other body (null when none)
  vec2 normal{0.0f, 0.0f};           ///< unit, pointing from the surface to the character
  vec2 point{0.0f, 0.0f};            ///< deepest contact point, metres
  vec2 velocity{0.0f, 0.0f};         ///< m/s of the surface's material at `point`
  float friction = 0.0f;             ///< the contact's mixed static friction coefficient
  /// True when this surface is valid.
  bool found() const { return !body.is_null(); }
};

/// Everything the controller carries from one update to the next (and draws): the surfaces
/// of the last update and the jump state. `Character::state` reads it and the restoring
/// constructor takes it back, so a saved run continues as the original.
struct CharacterState {
  CharacterSurface ground;   ///< walkable ground of the last update (also from ground snapping)
  CharacterSurface wall;     ///< wall of the last update
  CharacterSurface steep;    ///< ground too steep to stand on, last update
  CharacterSurface ceiling;  ///< surface above, last update
  CharacterSurface step;     ///< low wall the character can walk up, last update
  float step_height = 0.0f;  ///< metres from the feet to the top of `step`
  BodyId previous_ground_body;                 ///< ground of the update before (null in the air)
  vec2 previous_ground_velocity{0.0f, 0.0f};   ///< its velocity then, m/s

  CharacterSupport support = CharacterSupport::Air;    ///< where it was in the last update
  CharacterAction last_action = CharacterAction::None;  ///< what it did in the last update
  bool jump_was_held = false;          ///< jump button state of the last update
  bool may_snap = false;               ///< grounded last update without a jump or drop
  bool jumped_since_grounded = false;  ///< a jump or drop used the ground (no coyote after it)
  bool rising_hold = false;            ///< variable-height phase of the current jump
  bool press_buffered = false;         ///< a press is waiting for a chance to jump
  int buffer_age = 0;                  ///< updates since the buffered press
  int steps_since_grounded = 0;        ///< updates since the last grounded one (INT_MAX: never)
  int jumps_left = 0;                  ///< extra jumps left
  int lock_steps_left = 0;             ///< steps of horizontal-input lock left
  int coyote_steps_left = 0;           ///< steps of the coyote window left
  int buffer_steps_left = 0;           ///< steps a buffered press stays valid
  float gravity_scale = 1.0f;          ///< gravity scale set by the last update
};

/// A platformer character: its body in the world plus the controller's state.
class Character {
 public:
  /// Creates the character's body in `world`: dynamic, axis-aligned box, fixed rotation.
  /// Throws `Error` for invalid settings or definition.
  Character(World& world, const CharacterDef& def);
  /// Takes back a character saved with `state()`: `body` is its body in `world` (a world
  /// restored from a snapshot of the same moment), `def` the definition it was made from.
  /// Throws `Error` for invalid settings or a body that does not exist in `world`.
  Character(const World& world, BodyId body, const CharacterDef& def, const CharacterState& state);

  /// Runs the controller for the next step: reads `world.contacts()` (from the last step),
  /// decides jumps, sets the body's velocity and gravity scale. Call once before each
  /// `world.step()`. Throws `Error` if `input.move_x` is not finite.
  void update(World& world, const CharacterInput& input);

  /// Lets down + jump drop through the platforms of `platforms` (may be null).
  void set_one_way_platforms(const OneWayPlatforms* platforms) { one_way_platforms_ = platforms; }
  /// Replaces the tuning (validated; throws `Error`).
  void set_settings(const CharacterSettings& settings);
  /// The tuning.
  const CharacterSettings& settings() const { return settings_; }

  /// The character's body.
  BodyId body() const { return body_; }
  /// The controller's state carried between updates (for saving it with the world).
  const CharacterState& state() const { return state_; }
  /// m/s: the take-off speed of a jump, sqrt(2 |g| jump_height), under `world`'s gravity.
  float jump_speed(const World& world) const;

  /// True when the last update found walkable ground.
  bool grounded() const { return state_.support == CharacterSupport::Ground; }
  /// Where the character was in the last update.
  CharacterSupport support() const { return state_.support; }
  /// What it did in the last update.
  CharacterAction last_action() const { return state_.last_action; }
  /// The ground of the last update (not found in the air).
  const CharacterSurface& ground() const { return state_.ground; }
  /// The wall touched in the last update (not found when none).
  const CharacterSurface& wall() const { return state_.wall; }
  /// Extra jumps left.
  int jumps_left() const { return state_.jumps_left; }
  /// Updates since the last grounded one (0 while grounded).
  int steps_since_grounded() const { return state_.steps_since_grounded; }
  /// Steps of the coyote window left after the last update (0 when a ground jump is no longer
  /// possible or the character is grounded and needs none).
  int coyote_steps_left() const { return state_.coyote_steps_left; }
  /// Steps a buffered press stays valid after the last update (0 when none is buffered).
  int buffer_steps_left() const { return state_.buffer_steps_left; }
  /// Steps of horizontal-input lock left after a wall jump.
  int lock_steps_left() const { return state_.lock_steps_left; }
  /// Gravity scale set by the last update.
  float gravity_scale() const { return state_.gravity_scale; }

  /// Draws the character's overlays: ground normal (green), wall normal (orange), a coyote
  /// bar (yellow) and a buffer bar (magenta) under the feet, a dot per extra jump left above
  /// the head and a label with the numbers. Shapes themselves are drawn by `World::draw`.
  void draw(const World& world, DebugDraw& draw, Color label_color = Color{0.0f, 0.0f, 0.0f, 1.0f}) const;

 private:
  void sense_contacts(const World& world, vec2 up, float move_x);
  bool snap_to_ground(const World& world, vec2 up, float* push_distance);

  BodyId body_;
  vec2 half_extents_{0.0f, 0.0f};
  CharacterSettings settings_;
  const OneWayPlatforms* one_way_platforms_ = nullptr;

  CharacterState state_;
};

}  // namespace impulse2d

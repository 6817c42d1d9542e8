#include "gameplay/character.h"

#include "core/error.h"
#include "gameplay/one_way_platform.h"

#include <algorithm>
#include <climits>
#include <optional>
#include <cmath>
#include <string>

namespace impulse2d {

namespace {

constexpr float half_pi = 1.5707963f;

float move_toward(float value, float target, float max_change) {
  if (value < target) return std::min(value + max_change, target);
  return std::max(value - max_change, target);
}

float sign_of(float value) { return value > 0.0f ? 1.0f : (value < 0.0f ? -1.0f : 0.0f); }

// Up is against gravity; without gravity the character keeps +y as up.
vec2 up_from_gravity(vec2 gravity) {
  const float strength = glm::length(gravity);
  return strength > 0.0f ? -gravity / strength : vec2(0.0f, 1.0f);
}

// Velocity of `body`'s material at the world point `point`.
vec2 material_velocity(const BodyView& body, vec2 point) {
  return body.linear_velocity + cross(body.angular_velocity, point - body.transform.position);
}

// The horizontal (perpendicular to up) unit part of a surface normal, or zero.
vec2 horizontal_part(vec2 normal, vec2 up) {
  const vec2 across = normal - up * glm::dot(normal, up);
  const float length = glm::length(across);
  return length > 0.0f ? across / length : vec2(0.0f);
}

void require(bool condition, const char* field, const char* rule) {
  if (!condition) throw Error(std::string("CharacterSettings: ") + field + " " + rule);
}

}  // namespace

int window_steps(float seconds, float time_step) {
  if (!(std::isfinite(seconds) && seconds >= 0.0f)) {
    throw Error("window_steps: seconds must be finite and >= 0");
  }
  if (!(std::isfinite(time_step) && time_step > 0.0f)) {
    throw Error("window_steps: time_step must be finite and > 0");
  }
  return static_cast<int>(std::floor(static_cast<double>(seconds) / time_step + 1.0e-3));
}

void validate_character_settings(const CharacterSettings& s) {
  require(std::isfinite(s.max_slope) && s.max_slope > 0.0f && s.max_slope < half_pi, "max_slope",
          "must be in (0, pi/2)");
  require(std::isfinite(s.wall_angle) && s.wall_angle >= 0.0f &&
              s.wall_angle < half_pi - s.max_slope,
          "wall_angle", "must be in [0, pi/2 - max_slope) so walls and ground do not overlap");
  require(std::isfinite(s.max_speed) && s.max_speed >= 0.0f, "max_speed", "must be >= 0");
  require(std::isfinite(s.ground_acceleration) && s.ground_acceleration >= 0.0f,
          "ground_acceleration", "must be >= 0");
  require(std::isfinite(s.ground_deceleration) && s.ground_deceleration >= 0.0f,
          "ground_deceleration", "must be >= 0");
  require(std::isfinite(s.air_acceleration) && s.air_acceleration >= 0.0f, "air_acceleration",
          "must be >= 0");
  require(std::isfinite(s.full_traction_friction) && s.full_traction_friction >= 0.0f,
          "full_traction_friction", "must be >= 0");
  require(std::isfinite(s.jump_height) && s.jump_height >= 0.0f, "jump_height", "must be >= 0");
  require(std::isfinite(s.held_gravity_scale) && s.held_gravity_scale > 0.0f &&
              s.held_gravity_scale <= 1.0f,
          "held_gravity_scale", "must be in (0, 1]");
  require(std::isfinite(s.coyote_time) && s.coyote_time >= 0.0f, "coyote_time", "must be >= 0");
  require(std::isfinite(s.jump_buffer_time) && s.jump_buffer_time >= 0.0f, "jump_buffer_time",
          "must be >= 0");
  require(s.extra_jumps >= 0, "extra_jumps", "must be >= 0");
  require(std::isfinite(s.wall_slide_speed) && s.wall_slide_speed >= 0.0f, "wall_slide_speed",
          "must be >= 0");
  require(is_finite(s.wall_jump_velocity), "wall_jump_velocity", "must be finite");
  require(std::isfinite(s.wall_jump_lock_time) && s.wall_jump_lock_time >= 0.0f,
          "wall_jump_lock_time", "must be >= 0");
  require(std::isfinite(s.max_step_height) && s.max_step_height >= 0.0f, "max_step_height",
          "must be >= 0");
  require(std::isfinite(s.snap_distance) && s.snap_distance >= 0.0f, "snap_distance",
          "must be >= 0");
}

Character::Character(World& world, const CharacterDef& def) : settings_(def.settings) {
  validate_character_settings(settings_);
  BodyDef body_def;
  body_def.type = BodyType::Dynamic;
  body_def.position = def.position;
  body_def.fixed_rotation = true;
  body_def.material = def.material;
  body_def.collision_layers = def.collision_layers;
  body_def.user_data = def.user_data;
  // The controller senses ground, walls and steps from overlapping contacts and lets a step
  // through before the solver acts on it; a speculative contact would stop the walk at a
  // step's face a step earlier than the controller can see it.
  body_def.speculative = false;
  body_ = world.create_body(body_def, make_box(def.half_extents));
  half_extents_ = def.half_extents;
  state_.jumps_left = settings_.extra_jumps;
  state_.steps_since_grounded = INT_MAX;
  state_.jumped_since_grounded = true;  // no ground used yet: no coyote jump from the spawn point
}

Character::Character(const World& world, BodyId body, const CharacterDef& def,
                     const CharacterState& state)
    : body_(body), half_extents_(def.half_extents), settings_(def.settings), state_(state) {
  validate_character_settings(settings_);
  if (!world.is_valid(body_)) throw Error("Character: the saved character's body does not exist");
}

void Character::set_settings(const CharacterSettings& settings) {
  validate_character_settings(settings);
  settings_ = settings;
  state_.jumps_left = std::min(state_.jumps_left, settings_.extra_jumps);
}

float Character::jump_speed(const World& world) const {
  return std::sqrt(2.0f * glm::length(world.settings().gravity) * settings_.jump_height);
}

void Character::sense_contacts(const World& world, vec2 up, float move_x) {
  state_.ground = state_.wall = state_.steep = state_.ceiling = state_.step = CharacterSurface{};
  const BodyView self = world.body(body_);
  const vec2 self_moved = self.transform.position - self.previous_position;
  const vec2 feet = self.transform.position - up * half_extents_.y;
  const float ground_min_dot = cos_sin(settings_.max_slope).cosine;
  const float wall_max_dot = cos_sin(settings_.wall_angle).sine;
  const float move_sign = sign_of(move_x);
  const vec2 side = right_perpendicular(up);
  float best_ground_score = -2.0f;

  for (const Contact& contact : world.contacts()) {
    const bool self_is_a = contact.body_a == body_;
    if (!contact.enabled || (!self_is_a && contact.body_b != body_)) continue;
    const BodyId other_id = self_is_a ? contact.body_b : contact.body_a;
    const BodyView other = world.body(other_id);
    int deepest = 0;
    for (int i = 1; i < contact.point_count; ++i) {
      if (contact.points[i].depth > contact.points[deepest].depth) deepest = i;
    }
    CharacterSurface surface;
    surface.body = other_id;
    surface.normal = self_is_a ? -contact.normal : contact.normal;
    surface.point = contact.points[deepest].point;
    surface.velocity = material_velocity(other, surface.point);
    surface.friction = contact.static_friction;

    // Contacts are found at the start of a step; carry the depth over the step since taken.
    const vec2 other_moved = other.transform.position - other.previous_position;
    const float depth_now =
        contact.points[deepest].depth - glm::dot(self_moved - other_moved, surface.normal);
    if (depth_now <= 0.0f) continue;
    float top_above_feet = -1.0e30f;  // highest contact point above the feet, now
    for (int i = 0; i < contact.point_count; ++i) {
      top_above_feet = std::max(top_above_feet, glm::dot(contact.points[i].point - feet, up));
    }
    top_above_feet += glm::dot(self_moved - other_moved, up);

    const float normal_up = glm::dot(surface.normal, up);
    if (normal_up >= ground_min_dot) {
      // Among several grounds walk along the one that climbs most in the input direction
      // (so a foot on a flat does not push into the slope ahead); idle, the flattest.
      const vec2 tangent = right_perpendicular(surface.normal);
      const float score = move_sign == 0.0f ? normal_up : glm::dot(tangent * move_sign, up);
      if (score > best_ground_score) {
        best_ground_score = score;
        state_.ground = surface;
      }
    } else if (std::abs(normal_up) <= wall_max_dot) {
      if (top_above_feet <= settings_.max_step_height &&
          (!state_.step.found() || top_above_feet > state_.step_height)) {
        state_.step = surface;
        state_.step_height = top_above_feet;
      } else if (!state_.wall.found() || glm::dot(surface.normal, side) * move_sign < 0.0f) {
        state_.wall = surface;  // with a wall on each side, the one pressed into
      }
    } else if (normal_up < 0.0f) {
      state_.ceiling = surface;
    } else {
      state_.steep = surface;
    }
  }
}

bool Character::snap_to_ground(const World& world, vec2 up, float* push_distance) {
  const BodyView self = world.body(body_);
  const vec2 side = right_perpendicular(up);
  const float probe_start = 0.5f * half_extents_.y;  // rays start inside the own box
  const float probe_length = probe_start + settings_.snap_distance;
  const float ground_min_dot = cos_sin(settings_.max_slope).cosine;
  bool found = false;
  float nearest_gap = 0.0f;
  for (const float corner : {-1.0f, 1.0f}) {
    const vec2 origin = self.transform.position + side * (corner * 0.9f * half_extents_.x) -
                        up * (half_extents_.y - probe_start);
    const std::optional<RayHit> hit =
        world.raycast_closest(origin, -up * probe_length, self.collision_layers);
    if (!hit || hit->body == body_ || glm::dot(hit->normal, up) < ground_min_dot) continue;
    const float gap = hit->fraction * probe_length - probe_start;
    if (found && gap >= nearest_gap) continue;
    found = true;
    nearest_gap = gap;
    const BodyView other = world.body(hit->body);
    state_.ground.body = hit->body;
    state_.ground.normal = hit->normal;
    state_.ground.point = hit->point;
    state_.ground.velocity = material_velocity(other, hit->point);
    state_.ground.friction = mix_friction(self.material->static_friction, other.material->static_friction,
                                    world.settings().friction_mixing);
  }
  // Close the gap in one step and sink to half the allowed overlap, so the next step's
  // narrow phase finds the contact the solver keeps.
  if (found) *push_distance = std::max(0.0f, nearest_gap + 0.5f * world.settings().slop);
  return found;
}

void Character::update(World& world, const CharacterInput& input) {
  if (!std::isfinite(input.move_x)) throw Error("Character::update: input.move_x is not finite");
  const float move_x = std::clamp(input.move_x, -1.0f, 1.0f);
  const WorldSettings& world_settings = world.settings();
  const float dt = world_settings.time_step;
  const float gravity = glm::length(world_settings.gravity);
  const vec2 up = up_from_gravity(world_settings.gravity);
  const vec2 side = right_perpendicular(up);
  const BodyView self = world.body(body_);
  vec2 velocity = self.linear_velocity;
  const float mass = self.mass;

  const bool pressed = input.jump && !state_.jump_was_held;
  state_.jump_was_held = input.jump;
  state_.last_action = CharacterAction::None;

  // 1. Where are we: surfaces from the contacts, or ground to snap to.
  sense_contacts(world, up, move_x);
  const bool ground_contact = state_.ground.found();
  float snap_push = 0.0f;
  bool on_ground = ground_contact || (state_.may_snap && snap_to_ground(world, up, &snap_push));
  if (!on_ground && !state_.wall.found()) state_.wall = state_.step;  // off the ground a low wall is still a wall

  // 2. Timers, in steps at this world's time step.
  const int coyote_steps = window_steps(settings_.coyote_time, dt);
  const int buffer_steps = window_steps(settings_.jump_buffer_time, dt);
  if (on_ground) {
    state_.steps_since_grounded = 0;
    state_.jumps_left = settings_.extra_jumps;
    state_.jumped_since_grounded = false;
    state_.rising_hold = false;
  } else if (state_.steps_since_grounded < INT_MAX) {
    ++state_.steps_since_grounded;
  }
  if (pressed) {
    state_.press_buffered = true;
    state_.buffer_age = 0;
  } else if (state_.press_buffered && ++state_.buffer_age > buffer_steps) {
    state_.press_buffered = false;
  }
  bool input_locked = state_.lock_steps_left > 0;
  if (input_locked) --state_.lock_steps_left;

  // 3. Jumps, in order of preference: drop through, from the ground (or coyote), off a wall,
  // in the air.
  if (state_.press_buffered) {
    const float take_off_speed = jump_speed(world);
    const bool coyote = !state_.jumped_since_grounded && state_.steps_since_grounded <= coyote_steps;
    if (ground_contact && input.down && one_way_platforms_ != nullptr &&
        one_way_platforms_->contains(state_.ground.body)) {
      world.set_contact_enabled(body_, state_.ground.body, false);
      state_.last_action = CharacterAction::DropThrough;
    } else if (on_ground || coyote) {
      const float ground_rise = on_ground ? glm::dot(state_.ground.velocity, up) : 0.0f;
      velocity += up * (ground_rise + take_off_speed - glm::dot(velocity, up));
      state_.last_action = on_ground ? CharacterAction::GroundJump : CharacterAction::CoyoteJump;
    } else if (state_.wall.found()) {
      const vec2 away = horizontal_part(state_.wall.normal, up);
      velocity = state_.wall.velocity + away * settings_.wall_jump_velocity.x +
                 up * settings_.wall_jump_velocity.y;
      state_.lock_steps_left = window_steps(settings_.wall_jump_lock_time, dt);
      input_locked = true;
      state_.last_action = CharacterAction::WallJump;
    } else if (state_.jumps_left > 0) {
      --state_.jumps_left;
      velocity += up * (take_off_speed - glm::dot(velocity, up));
      state_.last_action = CharacterAction::AirJump;
    }
    if (state_.last_action != CharacterAction::None) {
      state_.press_buffered = false;
      state_.jumped_since_grounded = true;
      state_.rising_hold = state_.last_action != CharacterAction::DropThrough;
      on_ground = false;
    }
  }

  // 4. Motion.
  const float target_speed = move_x * settings_.max_speed;
  if (on_ground) {
    state_.support = CharacterSupport::Ground;
    // Walk along the ground relative to it (so platforms carry us); gravity off, so the
    // solver needs no normal impulse and friction does not fight the walk.
    const vec2 tangent = right_perpendicular(state_.ground.normal);
    // On the same ground as last update, keep the speed relative to what it did then, so a
    // platform that changes velocity takes us with it.
    const vec2 ground_before =
        state_.ground.body == state_.previous_ground_body ? state_.previous_ground_velocity : state_.ground.velocity;
    float along = glm::dot(velocity - ground_before, tangent);
    if (!input_locked) {
      const bool speeding_up = target_speed != 0.0f && along * target_speed >= 0.0f &&
                               std::abs(target_speed) > std::abs(along);
      float rate = speeding_up ? settings_.ground_acceleration : settings_.ground_deceleration;
      if (settings_.full_traction_friction > 0.0f) {
        rate *= std::min(1.0f, state_.ground.friction / settings_.full_traction_friction);
      }
      along = move_toward(along, target_speed, rate * dt);
    }
    for (const CharacterSurface* blocker : {&state_.wall, &state_.steep}) {
      if (blocker->found() && glm::dot(tangent * along, horizontal_part(blocker->normal, up)) < 0.0f) {
        along = 0.0f;  // do not walk into a wall or up a slope too steep to stand on
      }
    }
    velocity = state_.ground.velocity + tangent * along - up * (snap_push / dt);
    if (state_.step.found() && glm::dot(tangent * along, horizontal_part(state_.step.normal, up)) < 0.0f) {
      // Walking into a step: the solver would stop us at its face, so that contact is let
      // through until we part, and we rise onto the top within this step (half a slop above
      // it; snapping brings us down onto it).
      world.set_contact_enabled(body_, state_.step.body, false);
      const float lift = state_.step_height + 0.5f * world_settings.slop;
      velocity = state_.ground.velocity + side * glm::dot(tangent * along, side) + up * (lift / dt);
    }
    state_.gravity_scale = 0.0f;
    const BodyView ground_body = world.body(state_.ground.body);
    if (ground_body.type == BodyType::Dynamic) {
      world.apply_force(state_.ground.body, -up * (mass * gravity), state_.ground.point);  // our weight
    }
  } else {
    state_.support = CharacterSupport::Air;
    if (state_.steep.found() && state_.last_action == CharacterAction::None) {
      state_.support = CharacterSupport::SteepSlope;  // slides: gravity and the contact's friction act
    } else if (!input_locked) {
      const float horizontal = glm::dot(velocity, side);
      velocity += side * (move_toward(horizontal, target_speed, settings_.air_acceleration * dt) -
                          horizontal);
    }
    if (!input.jump || glm::dot(velocity, up) <= 0.0f || state_.ceiling.found()) state_.rising_hold = false;
    state_.gravity_scale = state_.rising_hold ? settings_.held_gravity_scale : 1.0f;

    // Neither walls nor steep slopes are pushed into (no friction holding us to them)...
    for (const CharacterSurface* blocker : {&state_.wall, &state_.steep}) {
      if (!blocker->found()) continue;
      const vec2 across = horizontal_part(blocker->normal, up);
      const float into = glm::dot(velocity - blocker->velocity, across);
      if (into < 0.0f) velocity -= across * into;
    }
    // ...and a ceiling stops the rise.
    if (state_.ceiling.found()) {
      const float into = glm::dot(velocity - state_.ceiling.velocity, state_.ceiling.normal);
      if (into < 0.0f) velocity -= state_.ceiling.normal * into;
    }
    // Pressing into a wall while falling: slide down it no faster than wall_slide_speed.
    const bool pressing_wall =
        state_.wall.found() && move_x * glm::dot(state_.wall.normal, side) < 0.0f && !input_locked;
    if (pressing_wall && state_.last_action == CharacterAction::None) {
      state_.support = CharacterSupport::WallSlide;
      const float rise = glm::dot(velocity, up);
      if (rise - gravity * state_.gravity_scale * dt < -settings_.wall_slide_speed) {
        velocity += up * (-settings_.wall_slide_speed - rise);
        state_.gravity_scale = 0.0f;
      }
    }
  }

  world.set_linear_velocity(body_, velocity);
  world.set_gravity_scale(body_, state_.gravity_scale);
  state_.may_snap = on_ground;
  state_.previous_ground_body = on_ground ? state_.ground.body : BodyId{};
  state_.previous_ground_velocity = state_.ground.velocity;
  state_.coyote_steps_left = (!on_ground && !state_.jumped_since_grounded)
                           ? std::max(0, coyote_steps - state_.steps_since_grounded)
                           : 0;
  state_.buffer_steps_left = state_.press_buffered ? buffer_steps - state_.buffer_age : 0;
}

}  // namespace impulse2d

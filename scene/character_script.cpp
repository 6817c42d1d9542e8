/// @file character_script.cpp
#include "scene/character_script.h"

#include "core/world.h"
#include "scene/script_state.h"

namespace impulse2d::demos {
namespace {

constexpr std::uint32_t state_version = 1;

void write_surface(ScriptStateWriter& out, const CharacterSurface& surface) {
  out.body(surface.body);
  out.vector(surface.normal);
  out.vector(surface.point);
  out.vector(surface.velocity);
  out.f32(surface.friction);
}

CharacterSurface read_surface(ScriptStateReader& in) {
  CharacterSurface surface;
  surface.body = in.body();
  surface.normal = in.vector();
  surface.point = in.vector();
  surface.velocity = in.vector();
  surface.friction = in.f32();
  return surface;
}

void write_character(ScriptStateWriter& out, const CharacterState& state) {
  for (const CharacterSurface* surface : {&state.ground, &state.wall, &state.steep, &state.ceiling, &state.step}) {
    write_surface(out, *surface);
  }
  out.f32(state.step_height);
  out.body(state.previous_ground_body);
  out.vector(state.previous_ground_velocity);
  out.u8(static_cast<std::uint8_t>(state.support));
  out.u8(static_cast<std::uint8_t>(state.last_action));
  for (const bool flag : {state.jump_was_held, state.may_snap, state.jumped_since_grounded,
                          state.rising_hold, state.press_buffered}) {
    out.boolean(flag);
  }
  for (const int count : {state.buffer_age, state.steps_since_grounded, state.jumps_left,
                          state.lock_steps_left, state.coyote_steps_left, state.buffer_steps_left}) {
    out.i32(count);
  }
  out.f32(state.gravity_scale);
}

CharacterState read_character(ScriptStateReader& in) {
  CharacterState state;
  for (CharacterSurface* surface : {&state.ground, &state.wall, &state.steep, &state.ceiling, &state.step}) {
    *surface = read_surface(in);
  }
  state.step_height = in.f32();
  state.previous_ground_body = in.body();
  state.previous_ground_velocity = in.vector();
  state.support = static_cast<CharacterSupport>(in.u8(static_cast<std::uint8_t>(CharacterSupport::SteepSlope)));
  state.last_action = static_cast<CharacterAction>(in.u8(static_cast<std::uint8_t>(CharacterAction::DropThrough)));
  for (bool* flag : {&state.jump_was_held, &state.may_snap, &state.jumped_since_grounded,
                     &state.rising_hold, &state.press_buffered}) {
    *flag = in.boolean();
  }
  for (int* count : {&state.buffer_age, &state.steps_since_grounded, &state.jumps_left,
                     &state.lock_steps_left, &state.coyote_steps_left, &state.buffer_steps_left}) {
    *count = in.i32(0);
  }
  state.gravity_scale = in.f32();
  return state;
}

}  // namespace

std::vector<std::string> CharacterScript::buttons() const { return {"left", "right", "jump", "down"}; }

void CharacterScript::button(World&, const std::string& name, bool pressed) {
  if (name == "left") left_ = pressed;
  if (name == "right") right_ = pressed;
  if (name == "jump") jump_ = pressed;
  if (name == "down") down_ = pressed;
}

void CharacterScript::before_step(World& world, std::int64_t) {
  if (!character_) {
    for (const BodyId id : world.body_ids()) {
      if (world.body(id).user_data == one_way_platform_tag) one_way_.add(id);
    }
    world.set_contact_filter(one_way_.filter());
    character_.emplace(world, def_);
    character_->set_one_way_platforms(&one_way_);
  }
  const float move = (right_ ? 1.0f : 0.0f) - (left_ ? 1.0f : 0.0f);
  character_->update(world, CharacterInput{move, jump_, down_});
}

std::vector<std::uint8_t> CharacterScript::save_state() const {
  ScriptStateWriter out(state_version);
  for (const bool held : {left_, right_, jump_, down_}) out.boolean(held);
  out.boolean(character_.has_value());
  if (character_) {
    const std::vector<OneWayPlatforms::Platform>& platforms = one_way_.platforms();
    out.u32(static_cast<std::uint32_t>(platforms.size()));
    for (const OneWayPlatforms::Platform& platform : platforms) {
      out.body(platform.body);
      out.vector(platform.up);
    }
    out.body(character_->body());
    write_character(out, character_->state());
  }
  return out.bytes();
}

void CharacterScript::restore_state(World& world, const std::vector<std::uint8_t>& bytes) {
  ScriptStateReader in(bytes, "character script", state_version);
  for (bool* held : {&left_, &right_, &jump_, &down_}) *held = in.boolean();
  if (!in.boolean()) {
    in.finish();
    // This script's filter (no platforms yet: every pair allowed) replaces whatever filter the
    // world carried, which may be another script's; the first step installs it again.
    world.set_contact_filter(one_way_.filter());
    return;
  }
  const std::uint32_t platforms = in.u32();
  if (platforms > static_cast<std::uint32_t>(world.body_count())) {
    in.fail("more one-way platforms than bodies");
  }
  for (std::uint32_t i = 0; i < platforms; ++i) {
    const BodyId id = in.body();
    if (!world.is_valid(id)) in.fail("a one-way platform that is not a body of the saved world");
    one_way_.add(id, in.vector());
  }
  const BodyId body = in.body();
  if (!world.is_valid(body)) in.fail("the character's body is not a body of the saved world");
  const CharacterState state = read_character(in);
  in.finish();
  world.set_contact_filter(one_way_.filter());
  character_.emplace(world, body, def_, state);
  character_->set_one_way_platforms(&one_way_);
}

std::optional<BodyId> CharacterScript::followed_body() const {
  if (!character_) return std::nullopt;
  return character_->body();
}

void CharacterScript::draw(const World& world, DebugDraw& draw, const DebugDrawOptions& options) const {
  if (character_) character_->draw(world, draw, options.palette.label);
}

}  // namespace impulse2d::demos

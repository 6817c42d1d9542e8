/// @file character_script.cpp
#include "scene/character_script.h"

#include "core/world.h"

namespace impulse2d::demos {

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

std::optional<BodyId> CharacterScript::followed_body() const {
  if (!character_) return std::nullopt;
  return character_->body();
}

void CharacterScript::draw(const World& world, DebugDraw& draw, const DebugDrawOptions& options) const {
  if (character_) character_->draw(world, draw, options.palette.label);
}

}  // namespace impulse2d::demos

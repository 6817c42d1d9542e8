/// @file character_draw.cpp
/// The character's debug overlays, through core's `DebugDraw` interface.

#include "gameplay/character.h"

#include <algorithm>
#include <string>

namespace impulse2d {

namespace {

constexpr Color ground_normal_color{0.10f, 0.65f, 0.20f, 1.0f};
constexpr Color wall_normal_color{0.95f, 0.55f, 0.10f, 1.0f};
constexpr Color coyote_color{0.95f, 0.80f, 0.10f, 1.0f};
constexpr Color buffer_color{0.85f, 0.20f, 0.75f, 1.0f};
constexpr Color empty_bar_color{0.30f, 0.30f, 0.30f, 0.5f};
constexpr Color jump_dot_color{0.15f, 0.35f, 0.90f, 1.0f};
constexpr float normal_arrow_length = 0.6f;  // metres
constexpr float jump_dot_pixels = 8.0f;

// A bar under the feet: grey track for the whole window, coloured part for what is left.
void draw_bar(DebugDraw& draw, vec2 left, float width, int left_steps, int window, Color color) {
  draw.draw_segment(left, left + vec2(width, 0.0f), empty_bar_color);
  if (window <= 0 || left_steps <= 0) return;
  const float fraction = std::min(1.0f, static_cast<float>(left_steps) / static_cast<float>(window));
  draw.draw_segment(left, left + vec2(width * fraction, 0.0f), color);
}

}  // namespace

void Character::draw(const World& world, DebugDraw& draw, Color label_color) const {
  const vec2 center = world.body(body_).transform.position;
  const float dt = world.settings().time_step;
  const int coyote_window = window_steps(settings_.coyote_time, dt);
  const int buffer_window = window_steps(settings_.jump_buffer_time, dt);

  if (state_.ground.found()) {
    draw.draw_arrow(state_.ground.point, state_.ground.point + state_.ground.normal * normal_arrow_length,
                    ground_normal_color);
  }
  if (state_.wall.found()) {
    draw.draw_arrow(state_.wall.point, state_.wall.point + state_.wall.normal * normal_arrow_length,
                    wall_normal_color);
  }

  const float width = 2.0f * half_extents_.x;
  const vec2 below_feet = center + vec2(-half_extents_.x, -half_extents_.y - 0.12f);
  draw_bar(draw, below_feet, width, state_.coyote_steps_left, coyote_window, coyote_color);
  draw_bar(draw, below_feet - vec2(0.0f, 0.1f), width, state_.buffer_steps_left, buffer_window,
           buffer_color);

  const vec2 above_head = center + vec2(-half_extents_.x, half_extents_.y + 0.15f);
  for (int i = 0; i < state_.jumps_left; ++i) {
    draw.draw_point(above_head + vec2(0.2f * static_cast<float>(i), 0.0f), jump_dot_pixels,
                    jump_dot_color);
  }
  draw.draw_text(above_head + vec2(0.0f, 0.15f),
                 "coyote " + std::to_string(state_.coyote_steps_left) + "/" +
                     std::to_string(coyote_window) + "  buffer " +
                     std::to_string(state_.buffer_steps_left) + "/" + std::to_string(buffer_window) +
                     "  jumps " + std::to_string(state_.jumps_left),
                 label_color);
}

}  // namespace impulse2d

// A level file loaded, stepped with a character on it, and drawn once: every installed
// library through <impulse2d/...> includes only. Exits 1 with a message when a result is wrong.
#include <impulse2d/core/world.h>
#include <impulse2d/gameplay/character.h>
#include <impulse2d/render/camera.h>
#include <impulse2d/render/frame_renderer.h>
#include <impulse2d/scene/scene_loader.h>
#include <impulse2d/scene/scene_model.h>

#include <cmath>
#include <cstdio>
#include <set>

#ifdef __FAST_MATH__
#error "impulse2d::core must switch fast-math off for its consumers"
#endif

namespace {

constexpr const char* kLevel = R"({
  "name": "level",
  "settings": {"gravity": [0, -10]},
  "model": {"shapes": ["box", "circle"]},
  "bodies": [
    {"name": "ground", "type": "static", "shape": {"type": "box", "half_extents": [20, 0.5]},
     "position": [0, -0.5]},
    {"name": "ball", "shape": {"type": "circle", "radius": 0.5}, "position": [-3, 4]}
  ]
})";

int fail(const char* what, double value) {
  std::fprintf(stderr, "consumer: %s (%g)\n", what, value);
  return 1;
}

}  // namespace

int main() {
  using namespace impulse2d;
  demos::Scene level = demos::parse_scene(kLevel, "level.json");
  demos::apply_model(level.model, level.settings);
  World world(level.settings);
  level.build(world, demos::Params(level.params));

  CharacterDef def;
  def.position = vec2(0.0f, 0.5f);
  Character character(world, def);
  CharacterInput walk;
  walk.move_x = 1.0f;
  for (int step = 0; step < 120; ++step) {
    character.update(world, walk);
    world.step();
  }
  const float ball_y = world.body(world.body_ids().at(1)).transform.position.y;  // created second
  if (std::fabs(ball_y - 0.5f) > 0.05f) return fail("the ball does not rest on the ground", ball_y);
  const float walked = world.body(character.body()).transform.position.x;
  if (walked < 1.0f) return fail("the character did not walk right", walked);

  render::FrameRenderer renderer(64, 48);
  const render::Frame frame = renderer.render(
      world, render::Camera::fit(render::world_bounds(world), 64, 48), render::FrameOptions{},
      render::HudInfo{"level", 120});
  std::set<std::uint32_t> colours;
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) {
      const render::Pixel pixel = frame.pixel(x, y);
      colours.insert(pixel.r | pixel.g << 8 | pixel.b << 16);
    }
  }
  if (colours.size() < 2) return fail("the frame is blank: colours", double(colours.size()));
  std::printf("consumer: ok, state hash %016llx, character at x = %.2f m\n",
              static_cast<unsigned long long>(world.state_hash()), walked);
  return 0;
}

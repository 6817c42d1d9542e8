// render_example: writes the README's example frame, a small scene with every overlay,
// the HUD, the legend and a motion trail.
//
//   render_example [--theme light|dark] OUTPUT.png
#include "core/world.h"
#include "render/camera.h"
#include "render/frame_renderer.h"
#include "render/motion_trails.h"
#include "render/palette.h"
#include "image/png.h"
#include "render/render_error.h"

#include <cstdio>
#include <string>

using namespace impulse2d;
using namespace impulse2d::render;

namespace {

// Ground, a five-row pyramid of rotating boxes, a ball thrown at it, a sliding box, a
// resting hexagon and a triangle that is put to sleep.
World make_scene(BodyId& ball, BodyId& sleeper) {
  World world;
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.material = materials::static_ground();
  ground.position = {0.0f, -0.5f};
  world.create_body(ground, make_box({9.0f, 0.5f}));

  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 5 - row; ++column) {
      BodyDef box;
      box.position = {-5.0f + 1.02f * static_cast<float>(column) + 0.51f * static_cast<float>(row),
                      0.5f + 1.0f * static_cast<float>(row)};
      world.create_body(box, make_oriented_box({0.5f, 0.5f}));
    }
  }
  BodyDef thrown;
  thrown.position = {-7.5f, 6.0f};
  thrown.linear_velocity = {6.5f, 1.0f};
  thrown.material = materials::bouncy_ball();
  ball = world.create_body(thrown, make_circle(0.45f));

  BodyDef slider;
  slider.position = {1.5f, 0.4f};
  slider.linear_velocity = {4.0f, 0.0f};
  world.create_body(slider, make_box({0.6f, 0.4f}));

  vec2 hexagon[6];
  for (int i = 0; i < 6; ++i) {
    const float angle = 1.0471976f * static_cast<float>(i);
    hexagon[i] = vec2(0.6f * std::cos(angle), 0.6f * std::sin(angle));
  }
  BodyDef hex;
  hex.position = {4.5f, 0.52f};
  world.create_body(hex, make_polygon(hexagon, 6));

  const vec2 triangle[3] = {{6.8f, 0.0f}, {8.4f, 0.0f}, {7.4f, 1.3f}};
  vec2 centroid;
  const Shape shape = make_polygon(triangle, 3, &centroid);
  BodyDef resting;
  resting.position = centroid;
  sleeper = world.create_body(resting, shape);
  return world;
}

}  // namespace

int main(int argc, char** argv) {
  Theme theme = Theme::Light;
  std::string output;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--theme" && i + 1 < argc) {
      const auto parsed = parse_theme(argv[++i]);
      if (!parsed) {
        std::fprintf(stderr, "render_example: --theme must be light or dark, not '%s'\n", argv[i]);
        return 2;
      }
      theme = *parsed;
    } else if (output.empty()) {
      output = argument;
    } else {
      output.clear();
      break;
    }
  }
  if (output.empty()) {
    std::fprintf(stderr, "usage: render_example [--theme light|dark] OUTPUT.png\n");
    return 2;
  }
  try {
    BodyId ball;
    BodyId sleeper;
    World world = make_scene(ball, sleeper);
    MotionTrails trails(60);
    trails.track(ball);
    constexpr int kSteps = 66;
    for (int i = 0; i < kSteps; ++i) {
      world.step();
      trails.record(world);
    }
    world.set_awake(sleeper, false);

    FrameRenderer renderer(800, 600);
    const Camera camera = Camera::fit(Aabb{vec2(-9.0f, -1.0f), vec2(9.0f, 7.0f)}, 800, 600, 12.0f);
    FrameOptions options;
    options.draw.flags = draw_all;
    options.draw.impulse_scale = 12.0f;
    options.draw.normal_length = 0.2f;
    options.draw.penetration_scale = 10.0f;
    options.theme = theme;
    options.trails = &trails;
    HudInfo hud;
    hud.scene_name = "overlays";
    hud.step = kSteps;
    image::save_png(output, renderer.render(world, camera, options, hud));
  } catch (const std::exception& error) {
    std::fprintf(stderr, "render_example: %s\n", error.what());
    return 1;
  }
  return 0;
}

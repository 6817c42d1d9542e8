// The HUD and the legend cover no body (issue 28, item 1): every built-in scene rendered at
// 320x240 (the golden frames' size) and at 1920x1080 with every overlay, a few steps each. A
// frame drawn with the HUD and legend is compared with the same frame drawn without them:
// inside the screen bounds of every body the frame shows whole the two must be identical, and
// at 320x240 the pixels the HUD and legend change must be at most 12 % of the frame. (A body
// running off the frame's edge is a follow camera's level, the platformer's floor and walls:
// no band of the frame can be kept free of it.)
#include "demos/scene_registry.h"
#include "frames/frame_sequence.h"
#include "frames/scene_camera.h"
#include "frames/view_frame_options.h"
#include "render/event_marks.h"
#include "render/frame_renderer.h"
#include "scene/scene_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace impulse2d;

namespace {

// The screen bounds of `box` (metres) in whole pixels, [x0, x1) x [y0, y1); `whole` when they
// lie inside the frame.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool whole = false;
};

PixelBox pixel_box(const render::Camera& camera, const Aabb& box) {
  const vec2 a = camera.world_to_pixel(box.lower);
  const vec2 b = camera.world_to_pixel(box.upper);
  PixelBox pixels;
  pixels.whole = std::min(a.x, b.x) >= 0.0f && std::min(a.y, b.y) >= 0.0f &&
                 std::max(a.x, b.x) <= static_cast<float>(camera.width()) &&
                 std::max(a.y, b.y) <= static_cast<float>(camera.height());
  pixels.x0 = std::clamp(static_cast<int>(std::floor(std::min(a.x, b.x))), 0, camera.width());
  pixels.x1 = std::clamp(static_cast<int>(std::ceil(std::max(a.x, b.x))), 0, camera.width());
  pixels.y0 = std::clamp(static_cast<int>(std::floor(std::min(a.y, b.y))), 0, camera.height());
  pixels.y1 = std::clamp(static_cast<int>(std::ceil(std::max(a.y, b.y))), 0, camera.height());
  return pixels;
}

// What the HUD and legend did to one frame.
struct Coverage {
  double area_fraction = 0.0;  // pixels changed by the HUD and legend over all pixels
  int body_pixels = 0;         // of those, pixels inside some body's screen bounds
  std::string first_body;      // the first body found under them ("" for none)
};

Coverage measure(const render::Frame& with, const render::Frame& without, const World& world,
                 const render::Camera& camera) {
  std::vector<char> changed(static_cast<std::size_t>(with.width) * static_cast<std::size_t>(with.height), 0);
  int changed_count = 0;
  for (int y = 0; y < with.height; ++y) {
    for (int x = 0; x < with.width; ++x) {
      if (with.pixel(x, y) != without.pixel(x, y)) {
        changed[static_cast<std::size_t>(y) * static_cast<std::size_t>(with.width) + static_cast<std::size_t>(x)] = 1;
        ++changed_count;
      }
    }
  }
  Coverage coverage;
  coverage.area_fraction = static_cast<double>(changed_count) / static_cast<double>(with.width * with.height);
  std::vector<char> counted(changed.size(), 0);
  for (const BodyId id : world.body_ids()) {
    const PixelBox box = pixel_box(camera, world.body(id).aabb);
    if (!box.whole) continue;
    for (int y = box.y0; y < box.y1; ++y) {
      for (int x = box.x0; x < box.x1; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(with.width) + static_cast<std::size_t>(x);
        if (!changed[at] || counted[at]) continue;
        counted[at] = 1;
        ++coverage.body_pixels;
        if (coverage.first_body.empty()) {
          coverage.first_body = "body " + std::to_string(id.index) + " at pixel (" + std::to_string(x) + ", " +
                                std::to_string(y) + ")";
        }
      }
    }
  }
  return coverage;
}

struct FrameSize {
  int width;
  int height;
};

class HudAndLegendLayout : public ::testing::TestWithParam<std::string> {};

TEST_P(HudAndLegendLayout, CoverNoBodyAndAtMostTwelvePercentOfA320x240Frame) {
  const demos::Scene& scene = *demos::find_builtin_scene(GetParam());
  for (const FrameSize size : {FrameSize{320, 240}, FrameSize{1920, 1080}}) {
    demos::SceneRun run(scene, demos::Params(scene.params));
    render::FrameRenderer renderer(size.width, size.height);
    const render::Camera camera = demos::scene_camera(scene.view.camera, run.world(), size.width, size.height);
    DebugDrawOptions draw = scene.view.draw;
    draw.flags = draw_all | draw_events;  // every overlay (the events one is not in `all`)
    render::FrameOptions options = demos::view_frame_options(run, draw, render::Theme::Light);
    render::FrameOptions bare = options;
    bare.show_hud = false;
    bare.show_legend = false;
    // Each frame shows the events since the one before, as `render` draws them.
    render::EventMarks events;
    options.events = &events;
    bare.events = &events;
    double worst_area = 0.0;
    // Three steps: the start, early motion and later (capped at the scene's run).
    for (const std::int64_t step : {std::int64_t{0}, std::int64_t{60}, std::int64_t{180}}) {
      const std::int64_t at = std::min<std::int64_t>(step, scene.view.steps);
      events.clear();
      while (run.step_count() < at) {
        run.step();
        events.record(run.world(), run.step_count());
      }
      render::HudInfo hud;
      hud.scene_name = demos::scene_title(scene);
      hud.step = at;
      demos::update_view_frame(run, options, hud);
      demos::update_view_frame(run, bare, hud);
      const render::Camera frame_camera = demos::frame_camera(camera, run);
      const render::Frame with = renderer.render(run.world(), frame_camera, options, hud);
      const render::Frame without = renderer.render(run.world(), frame_camera, bare, hud);
      const Coverage coverage = measure(with, without, run.world(), frame_camera);
      worst_area = std::max(worst_area, coverage.area_fraction);
      const std::string where = scene.name + " at " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                ", step " + std::to_string(at);
      EXPECT_EQ(coverage.body_pixels, 0) << where << ": the HUD or legend covers " << coverage.first_body
                                         << " (" << coverage.body_pixels << " body pixels)";
      if (size.width == 320) {
        EXPECT_LE(coverage.area_fraction, 0.12) << where;
      }
    }
    std::printf("[ coverage ] %s %dx%d: HUD + legend change at most %.1f %% of the frame\n", scene.name.c_str(),
                size.width, size.height, 100.0 * worst_area);
  }
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, HudAndLegendLayout, ::testing::ValuesIn([] {
                           std::vector<std::string> names;
                           for (const demos::Scene& scene : demos::builtin_scenes()) names.push_back(scene.name);
                           return names;
                         }()),
                         [](const auto& test) { return test.param; });

}  // namespace

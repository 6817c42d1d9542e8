// Rendering a World: every overlay flag changes the frame, all flags off draw nothing,
// the HUD shows wall-clock figures only when given them, and frames are reproducible.
#include "render/frame_renderer.h"
#include "render/hud.h"
#include "render/motion_trails.h"
#include "render/palette.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;
using impulse2d::render::testing::make_overlay_scene;
using impulse2d::render::testing::to_pixel;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;

FrameOptions bare_options(std::uint32_t flags) {
  FrameOptions options;
  options.draw.flags = flags;
  options.draw.penetration_scale = 20.0f;  // the settled overlap is ~1 cm: make it visible
  options.show_hud = false;
  options.show_legend = false;
  return options;
}

Camera scene_camera(const World& world) { return Camera::fit(world_bounds(world), kWidth, kHeight, 8.0f); }

const std::vector<std::pair<DebugDrawFlag, const char*>>& overlay_flags() {
  static const std::vector<std::pair<DebugDrawFlag, const char*>> flags = {
      {draw_aabbs, "aabbs"},
      {draw_contact_points, "contact points"},
      {draw_contact_normals, "contact normals"},
      {draw_normal_impulses, "normal impulses"},
      {draw_friction_impulses, "friction impulses"},
      {draw_penetration, "penetration"},
      {draw_velocities, "velocities"},
      {draw_center_of_mass, "centre of mass"},
      {draw_sleeping, "sleeping"},
      {draw_broad_phase, "broad phase"},
      {draw_body_ids, "body ids"},
  };
  return flags;
}

}  // namespace

TEST(RenderWorld, SceneHasEveryOverlayToShow) {
  const World world = make_overlay_scene(20);
  bool friction = false;
  bool penetration = false;
  for (const Contact& contact : world.contacts()) {
    for (int i = 0; i < contact.point_count; ++i) {
      friction = friction || contact.points[i].tangent_impulse != 0.0f;
      penetration = penetration || contact.points[i].depth > 0.0f;
    }
  }
  EXPECT_TRUE(friction);
  EXPECT_TRUE(penetration);
  EXPECT_GE(world.contacts().size(), 3u);
}

TEST(RenderWorld, AllFlagsOffDrawsNothing) {
  const World world = make_overlay_scene(20);
  FrameRenderer renderer(kWidth, kHeight);
  const Frame frame = renderer.render(world, scene_camera(world), bare_options(0), HudInfo{});
  const Pixel background = to_pixel(theme_palette(Theme::Light).background);
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) ASSERT_EQ(frame.pixel(x, y), background) << x << "," << y;
  }
}

TEST(RenderWorld, EveryOverlayFlagChangesTheImage) {
  const World world = make_overlay_scene(20);
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = scene_camera(world);
  const Frame shapes_only = renderer.render(world, camera, bare_options(draw_shapes), HudInfo{});
  const Frame nothing = renderer.render(world, camera, bare_options(0), HudInfo{});
  EXPECT_NE(shapes_only.hash(), nothing.hash());
  for (const auto& [flag, name] : overlay_flags()) {
    const Frame with_overlay = renderer.render(world, camera, bare_options(draw_shapes | flag), HudInfo{});
    EXPECT_NE(with_overlay.hash(), shapes_only.hash()) << name << " over shapes changed nothing";
    EXPECT_TRUE(with_overlay.is_opaque()) << name;
    if (flag == draw_sleeping) continue;  // it only changes how shapes are filled
    const Frame alone = renderer.render(world, camera, bare_options(flag), HudInfo{});
    EXPECT_NE(alone.hash(), nothing.hash()) << name << " alone drew nothing";
  }
}

TEST(RenderWorld, BothThemesAreOpaqueAndDiffer) {
  const World world = make_overlay_scene(20);
  FrameRenderer renderer(kWidth, kHeight);
  FrameOptions options;
  options.draw.flags = draw_all;
  options.show_legend = false;  // at this size it sits in the bottom-right corner, over the pixel checked
  const Frame light = renderer.render(world, scene_camera(world), options, impulse2d::render::testing::hud("overlays", 20));
  options.theme = Theme::Dark;
  const Frame dark = renderer.render(world, scene_camera(world), options, impulse2d::render::testing::hud("overlays", 20));
  EXPECT_TRUE(light.is_opaque());
  EXPECT_TRUE(dark.is_opaque());
  EXPECT_NE(light.hash(), dark.hash());
  EXPECT_EQ(light.pixel(kWidth / 2, kHeight - 1), to_pixel(theme_palette(Theme::Light).background));
  EXPECT_EQ(dark.pixel(kWidth / 2, kHeight - 1), to_pixel(theme_palette(Theme::Dark).background));
}

TEST(RenderWorld, HudAndLegendDrawAndAreReproducible) {
  const World world = make_overlay_scene(20);
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = scene_camera(world);
  FrameOptions options = bare_options(draw_shapes | draw_contact_normals);
  const Frame plain = renderer.render(world, camera, options, impulse2d::render::testing::hud("scene", 3));
  options.show_hud = true;
  const Frame hud = renderer.render(world, camera, options, impulse2d::render::testing::hud("scene", 3));
  options.show_legend = true;
  const Frame legend = renderer.render(world, camera, options, impulse2d::render::testing::hud("scene", 3));
  const Frame legend_again = renderer.render(world, camera, options, impulse2d::render::testing::hud("scene", 3));
  const Frame next_frame = renderer.render(world, camera, options, impulse2d::render::testing::hud("scene", 4));
  EXPECT_NE(plain.hash(), hud.hash());
  EXPECT_NE(hud.hash(), legend.hash());
  EXPECT_EQ(legend.rgba, legend_again.rgba);
  EXPECT_NE(legend.hash(), next_frame.hash());
}

TEST(RenderWorld, WallClockFiguresOnlyWhenAsked) {
  HudCounts counts;
  counts.simulated_time = 1.5;
  counts.body_count = 7;
  counts.contact_count = 3;
  counts.contact_point_count = 5;
  HudInfo info = impulse2d::render::testing::hud("stack", 90);
  const auto joined = [&] {
    std::string text;
    for (const std::string& field : hud_text(info, counts).fields) text += field + "|";
    return text;
  };
  const std::string without = joined();
  EXPECT_EQ(without, "stack|step 90|t = 1.500 s|bodies 7|contacts 3 (5 points)|") << without;
  info.frame_index = 90;  // the same as the step: not repeated
  EXPECT_EQ(joined(), without);
  info.frame_index = 30;
  EXPECT_NE(joined().find("step 90|frame 30|"), std::string::npos) << joined();
  info.step_milliseconds = 1.25;
  info.frames_per_second = 75.0;
  const std::string with = joined();
  EXPECT_NE(with.find("last step 1.25 ms"), std::string::npos) << with;
  EXPECT_NE(with.find("75.0 frames/s"), std::string::npos) << with;
}

TEST(RenderWorld, LegendListsTheOverlaysDrawnWithScalesInItsNotes) {
  DebugDrawOptions options;
  options.impulse_scale = 0.5f;
  options.velocity_scale = 0.1f;
  const Camera camera = Camera::centered(vec2(0.0f), 25.0f, 100, 100);  // 50 px = 2 m
  const std::uint32_t drawn = draw_shapes | draw_normal_impulses | draw_velocities;
  const std::vector<LegendEntry> entries = legend_entries(options, drawn, false, Color{});
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].label, "impulse");
  EXPECT_EQ(entries[1].label, "velocity");
  const std::vector<LegendEntry> notes = legend_notes(options, drawn, camera, 120.0f, 4.0f);
  ASSERT_EQ(notes.size(), 3u);
  EXPECT_EQ(notes[0].label, "impulse 50 px = 4 N s");
  EXPECT_EQ(notes[1].label, "velocity 50 px = 20 m/s");
  EXPECT_EQ(notes[2].label, "arrows cut at 120 px //");
  EXPECT_FALSE(notes[0].swatch);
  EXPECT_EQ(legend_entries(options, drawn, true, Color{}).back().label, "trail");
  EXPECT_EQ(legend_entries(options, draw_all, false, Color{}).size(), 13u);
  options.penetration_scale = 10.0f;
  EXPECT_EQ(legend_notes(options, draw_penetration, camera, 240.0f, 8.0f)[0].label, "depth x10, >= 8 px");
  // Only what the world draws: a world without contacts has no contact entries.
  World world;
  BodyDef ground;
  ground.type = BodyType::Static;
  world.create_body(ground, make_box({2.0f, 0.5f}));
  EXPECT_EQ(drawn_overlay_flags(world, draw_all), draw_shapes | draw_aabbs | draw_center_of_mass | draw_body_ids);
}

TEST(RenderWorld, MotionTrailsDrawTheRecordedPath) {
  World world = make_overlay_scene(0);
  const std::vector<BodyId> ids = world.body_ids();
  MotionTrails trails(50);
  trails.track(ids[4]);  // the falling ball
  trails.track(ids[4]);
  ASSERT_EQ(trails.tracked().size(), 1u);
  for (int i = 0; i < 30; ++i) {
    world.step();
    trails.record(world);
  }
  FrameRenderer renderer(kWidth, kHeight);
  const Camera camera = scene_camera(world);
  FrameOptions options = bare_options(draw_shapes);
  const Frame without = renderer.render(world, camera, options, HudInfo{});
  options.trails = &trails;
  const Frame with = renderer.render(world, camera, options, HudInfo{});
  EXPECT_NE(without.hash(), with.hash());
  trails.clear();
  const Frame cleared = renderer.render(world, camera, options, HudInfo{});
  EXPECT_EQ(without.rgba, cleared.rgba);
}

TEST(RenderWorld, SameWorldTwiceIsBitIdentical) {
  FrameOptions options;
  options.draw.flags = draw_all;
  FrameRenderer renderer(kWidth, kHeight);
  const World first_world = make_overlay_scene(25);
  const World second_world = make_overlay_scene(25);
  const Frame first = renderer.render(first_world, scene_camera(first_world), options, impulse2d::render::testing::hud("twice", 25));
  const Frame second = renderer.render(second_world, scene_camera(second_world), options, impulse2d::render::testing::hud("twice", 25));
  EXPECT_EQ(first.rgba, second.rgba);
}

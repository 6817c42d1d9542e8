// Overlays that read at any size: contact arrows cut at their maximum length with a break
// mark, normals and impulses side by side, penetration bars visible at resting depths, text
// and lines scaled with the frame, and a legend that never covers the HUD (320x240 .. 4K).
#include "render/contact_overlay.h"
#include "render/easy_font.h"
#include "render/frame_renderer.h"
#include "render/frame_scale.h"
#include "render/hud.h"
#include "render/hud_layout.h"
#include "render/island_overlay.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include <string>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;
namespace support = impulse2d::render::testing;

namespace {

constexpr Color kArrow{0.8f, 0.3f, 0.1f, 1.0f};
constexpr Color kWhite{1.0f, 1.0f, 1.0f, 1.0f};

// Rows of column `column` that are not the white background.
int inked_rows(const Frame& frame, int column) {
  int count = 0;
  for (int y = 0; y < frame.height; ++y) count += frame.pixel(column, y) != support::to_pixel(kWhite) ? 1 : 0;
  return count;
}

// The rightmost inked column of row `row`, -1 when none.
int last_inked_column(const Frame& frame, int row) {
  int last = -1;
  for (int x = 0; x < frame.width; ++x) {
    if (frame.pixel(x, row) != support::to_pixel(kWhite)) last = x;
  }
  return last;
}

// The longest HUD a frame has without extra lines: long scene title, big counts.
HudText worst_hud() {
  HudInfo info = support::hud("random_polygons - 5 kinds, 40 bodies", 99999);
  info.frame_index = 33333;
  HudCounts counts;
  counts.simulated_time = 999.999;
  counts.body_count = 1000;
  counts.contact_count = 2000;
  counts.contact_point_count = 4000;
  return hud_text(info, counts);
}

}  // namespace

TEST(RenderOverlays, FrameScaleGrowsWithTheShorterSide) {
  EXPECT_EQ(frame_scale(320, 240), 1);
  EXPECT_EQ(frame_scale(800, 600), 1);
  EXPECT_EQ(frame_scale(1920, 1080), 2);
  EXPECT_EQ(frame_scale(4000, 3000), 6);
  EXPECT_EQ(frame_scale(16, 16), 1);
}

TEST(RenderOverlays, LongArrowIsCutAtItsMaximumWithABreakMark) {
  FrameRenderer renderer(400, 100);
  const Camera camera = Camera::centered(vec2(0.0f), 10.0f, 400, 100);  // x = -20 m at column 0
  Frame cut;
  bool was_cut = false;
  renderer.render_primitives(camera, kWhite, [&](PrimitiveRenderer& draw) {
    was_cut = draw_clamped_arrow(draw, vec2(-15.0f, 0.0f), vec2(15.0f, 0.0f), kArrow, 100.0f);
  }, cut);
  EXPECT_TRUE(was_cut);
  // The 300-pixel arrow starts at column 50 and stops at 150 (100 px), not at 350.
  const int tip = last_inked_column(cut, 50);
  EXPECT_GE(tip, 148);
  EXPECT_LE(tip, 151);
  // The break mark: strokes across the shaft around column 50 + 60 = 110 reach well above it.
  EXPECT_GT(inked_rows(cut, 110), inked_rows(cut, 80) + 4);

  Frame short_arrow;
  renderer.render_primitives(camera, kWhite, [&](PrimitiveRenderer& draw) {
    was_cut = draw_clamped_arrow(draw, vec2(-15.0f, 0.0f), vec2(-10.0f, 0.0f), kArrow, 100.0f);
  }, short_arrow);
  EXPECT_FALSE(was_cut);
  const int short_tip = last_inked_column(short_arrow, 50);
  EXPECT_GE(short_tip, 98);
  EXPECT_LE(short_tip, 101);
}

TEST(RenderOverlays, LinesAndTextGrowWithTheFrame) {
  // The same 1-metre-wide segment (world) at scale 1 and at scale 4 (1920x1920).
  const auto thickness = [](int side) {
    FrameRenderer renderer(side, side);
    const Camera camera = Camera::centered(vec2(0.0f), static_cast<float>(side) / 10.0f, side, side);
    Frame frame;
    renderer.render_primitives(camera, kWhite, [&](PrimitiveRenderer& draw) {
      draw.draw_segment(vec2(-4.0f, 0.1f), vec2(4.0f, 0.1f), kArrow);
    }, frame);
    return inked_rows(frame, side / 2);
  };
  const int small = thickness(480);
  const int large = thickness(1920);
  EXPECT_GE(small, 2);
  EXPECT_GE(large, 4 * small - 2);
  // Text: the HUD panel of a 4000x3000 frame is 6 times that of a 320x240 one.
  const HudText text{{"frame 00001", "t = 0.000 s"}, {}};
  const HudLayout small_hud = layout_hud(320, 240, text, {}, {}, frame_scale(320, 240));
  const HudLayout large_hud = layout_hud(4000, 3000, text, {}, {}, frame_scale(4000, 3000));
  EXPECT_FLOAT_EQ(large_hud.hud.height, 6.0f * small_hud.hud.height);
}

TEST(RenderOverlays, HudAndLegendStayInTheirBandsWithinTheAreaBudget) {
  DebugDrawOptions options;
  options.penetration_scale = 10.0f;
  const HudText hud = worst_hud();
  const std::vector<std::pair<int, int>> sizes = {{320, 240}, {400, 300}, {640, 480}, {800, 600},
                                                  {1024, 768}, {1920, 1080}, {3840, 2160}, {4000, 3000}};
  for (const auto& [width, height] : sizes) {
    const int scale = frame_scale(width, height);
    const Camera camera = Camera::centered(vec2(0.0f), 40.0f, width, height);
    const PanelBands bands = panel_bands(scale);
    const std::vector<LegendEntry> entries = legend_entries(options, draw_all, false, Color{});
    const std::vector<LegendEntry> notes = legend_notes(options, draw_all, camera, 120.0f * static_cast<float>(scale),
                                                        8.0f * static_cast<float>(scale));
    const HudLayout layout = layout_hud(width, height, hud, entries, notes, scale);
    const std::string where = std::to_string(width) + "x" + std::to_string(height);
    EXPECT_FALSE(layout.hud.overlaps(layout.legend)) << where;
    EXPECT_LE(layout.hud.top + layout.hud.height, bands.top) << where;
    EXPECT_GE(layout.legend.top, static_cast<float>(height) - bands.bottom) << where;
    EXPECT_LE(layout.hud.width, static_cast<float>(width)) << where;
    EXPECT_LE(layout.legend.width, static_cast<float>(width)) << where;
    EXPECT_LE(layout.hud.area() + layout.legend.area(),
              panel_area_budget * static_cast<float>(width) * static_cast<float>(height))
        << where;
    EXPECT_EQ(layout.hud_lines.size(), 1u) << where;
    EXPECT_EQ(layout.hud_lines[0].rfind("random_polygons", 0), 0u) << where;
    EXPECT_NE(layout.hud_lines[0].find("step 99999"), std::string::npos) << where;
  }
}

TEST(RenderOverlays, HudLineDropsTheDescriptionThenTrailingFieldsToFit) {
  const HudText text{{"tutorial - left: no friction | right: friction", "step 300", "frame 100", "t = 5.000 s",
                      "bodies 38", "contacts 14 (19 points)"},
                     {}};
  const HudLayout small = layout_hud(320, 240, text, {}, {}, 1);
  ASSERT_EQ(small.hud_lines.size(), 1u);
  EXPECT_EQ(small.hud_lines[0].rfind("tutorial  step 300  frame 100", 0), 0u) << small.hud_lines[0];
  EXPECT_LE(text_width(small.hud_lines[0]) + 2.0f * hud_panel_padding, 320.0f);
  const HudLayout wide = layout_hud(1600, 1200, text, {}, {}, 1);
  EXPECT_NE(wide.hud_lines[0].find("no friction"), std::string::npos);
  EXPECT_NE(wide.hud_lines[0].find("contacts 14"), std::string::npos);
}

TEST(RenderOverlays, LegendRowsAreBalancedAndNotesGoWhenTheyDoNotFit) {
  const std::vector<LegendEntry> entries(8, LegendEntry{Color{}, "normal"});
  const std::vector<LegendEntry> notes = {{Color{}, "a long note about the scale of the arrows", false}};
  const HudLayout wide = layout_hud(1600, 1200, HudText{}, entries, notes, 1);
  EXPECT_EQ(wide.legend_entries.size(), 9u);
  EXPECT_FLOAT_EQ(wide.legend.top + wide.legend.height, 1200.0f);
  const HudLayout narrow = layout_hud(160, 120, HudText{}, entries, notes, 1);
  EXPECT_EQ(narrow.legend_entries.size(), 8u);  // the note would need a third row
  // Two rows of four: the second row starts with the fifth entry, at the left edge.
  EXPECT_EQ(narrow.legend_entries[4].text_top, narrow.legend_entries[0].text_top + hud_row_pitch);
}

TEST(RenderOverlays, ContactMarksDrawNormalsBesideImpulsesAndRestingPenetration) {
  const World world = support::make_overlay_scene(60);  // resting contacts, ~1 cm overlaps
  FrameRenderer renderer(640, 480);
  const Camera camera = Camera::fit(world_bounds(world), 640, 480, 8.0f);
  FrameOptions options;
  options.show_hud = false;
  options.show_legend = false;
  options.draw.flags = draw_shapes;
  const Frame shapes = renderer.render(world, camera, options, HudInfo{});
  options.draw.flags = draw_shapes | draw_penetration;
  options.draw.penetration_scale = 1.0f;  // true length: sub-pixel, the bar's minimum shows it
  const Frame penetration = renderer.render(world, camera, options, HudInfo{});
  EXPECT_NE(shapes.hash(), penetration.hash());
  options.draw.flags = draw_shapes | draw_contact_normals;
  const Frame normals = renderer.render(world, camera, options, HudInfo{});
  options.draw.flags = draw_shapes | draw_contact_normals | draw_normal_impulses;
  const Frame both = renderer.render(world, camera, options, HudInfo{});
  // Normals stay visible under impulses: every normal pixel of `normals` that differs from
  // `shapes` is still normal-coloured (not covered) in `both` for most of them.
  const Pixel normal_colour = support::to_pixel(theme_palette(Theme::Light).debug.contact_normal);
  int normal_pixels = 0;
  int still_visible = 0;
  for (int y = 0; y < normals.height; ++y) {
    for (int x = 0; x < normals.width; ++x) {
      if (normals.pixel(x, y) != normal_colour) continue;
      ++normal_pixels;
      still_visible += both.pixel(x, y) == normal_colour ? 1 : 0;
    }
  }
  ASSERT_GT(normal_pixels, 20);
  EXPECT_GT(still_visible, normal_pixels * 8 / 10);
}

TEST(RenderOverlays, IslandsJoinDynamicBodiesThroughContactsOnly) {
  const World world = support::make_overlay_scene(60);
  const std::vector<int> island = island_of_slots(world);
  ASSERT_EQ(island.size(), static_cast<std::size_t>(world.body_count()));  // no slot is free
  int joined = 0;
  for (const Contact& contact : world.contacts()) {
    const BodyView a = world.body(contact.body_a);
    const BodyView b = world.body(contact.body_b);
    if (a.type == BodyType::Dynamic && b.type == BodyType::Dynamic && contact.enabled) {
      EXPECT_EQ(island[contact.body_a.index], island[contact.body_b.index]);
      ++joined;
    }
  }
  EXPECT_GT(joined, 0) << "the overlay scene's stack has dynamic-dynamic contacts";
  for (const BodyId id : world.body_ids()) {
    if (world.body(id).type != BodyType::Dynamic) {
      EXPECT_EQ(island[id.index], -1);
    }
  }
  EXPECT_EQ(*std::max_element(island.begin(), island.end()) + 1,
            static_cast<int>(std::set<int>(island.begin(), island.end()).size()) - 1)
      << "islands are numbered 0, 1, ... without gaps";
}

TEST(RenderOverlays, IslandsAndFeatureIdsDrawOnlyWhenAsked) {
  const World world = support::make_overlay_scene(60);
  FrameRenderer renderer(320, 240);
  const Camera camera = Camera::fit(world_bounds(world), 320, 240, 8.0f);
  FrameOptions options;
  options.show_hud = false;
  options.show_legend = false;
  const Frame plain = renderer.render(world, camera, options, HudInfo{});
  options.islands = true;
  const Frame islands = renderer.render(world, camera, options, HudInfo{});
  options.islands = false;
  options.contacts.feature_ids = true;
  const Frame ids = renderer.render(world, camera, options, HudInfo{});
  EXPECT_NE(plain.hash(), islands.hash());
  EXPECT_NE(plain.hash(), ids.hash());
  EXPECT_NE(islands.hash(), ids.hash());
}

TEST(RenderOverlays, SleepingContactsAreDrawnDimmedAndCountedInTheHud) {
  WorldSettings settings;
  settings.enable_sleeping = true;
  World world(settings);
  BodyDef ground;
  ground.type = BodyType::Static;
  ground.position = {0.0f, -0.5f};
  world.create_body(ground, make_box({4.0f, 0.5f}));
  BodyDef crate;
  crate.position = {0.0f, 0.5f};
  const BodyId box = world.create_body(crate, make_oriented_box({0.5f, 0.5f}));
  for (int i = 0; i < 600 && world.body(box).awake; ++i) world.step();
  ASSERT_FALSE(world.body(box).awake);
  world.step();  // the asleep pair's contact is set aside at the next step
  ASSERT_TRUE(world.contacts().empty());
  ASSERT_EQ(world.sleeping_contacts().size(), 1u);

  FrameRenderer renderer(320, 240);
  const Camera camera = Camera::fit(world_bounds(world), 320, 240, 8.0f);
  FrameOptions options;
  options.show_hud = false;
  options.show_legend = false;
  options.draw.flags = draw_shapes;
  const Frame shapes = renderer.render(world, camera, options, HudInfo{});
  options.draw.flags = draw_shapes | draw_contact_points;
  const Frame asleep = renderer.render(world, camera, options, HudInfo{});
  const Pixel full = support::to_pixel(theme_palette(Theme::Light).debug.contact_point);
  auto full_colour_pixels = [&full](const Frame& frame) {
    int count = 0;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) count += frame.pixel(x, y) == full ? 1 : 0;
    }
    return count;
  };
  EXPECT_NE(asleep.hash(), shapes.hash()) << "the sleeping contact was not drawn";
  EXPECT_EQ(full_colour_pixels(asleep), 0) << "the sleeping contact was not dimmed";

  world.set_awake(box, true);
  world.step();
  ASSERT_EQ(world.contacts().size(), 1u);
  const Frame awake = renderer.render(world, camera, options, HudInfo{});
  EXPECT_GT(full_colour_pixels(awake), 4) << "an awake contact is drawn at full colour";

  HudCounts counts;
  counts.contact_count = 0;
  counts.sleeping_contact_count = 3;
  EXPECT_NE(hud_text(support::hud("s", 0), counts).fields.back().find("+ 3 sleeping"), std::string::npos);
  counts.sleeping_contact_count = 0;
  EXPECT_EQ(hud_text(support::hud("s", 0), counts).fields.back().find("sleeping"), std::string::npos);
}

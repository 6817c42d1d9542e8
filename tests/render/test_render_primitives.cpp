// The renderer below the world: camera mapping, context errors, and known colours at known
// pixels for hand-made primitives.
#include "render/camera.h"
#include "render/easy_font.h"
#include "render/frame_renderer.h"
#include "render/offscreen_context.h"
#include "render/render_error.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace impulse2d;
using namespace impulse2d::render;
using impulse2d::render::testing::to_pixel;

namespace {

constexpr Color kWhite{1.0f, 1.0f, 1.0f, 1.0f};
constexpr Color kFill{0.2f, 0.6f, 0.4f, 1.0f};
constexpr Color kOutline{0.0f, 0.0f, 0.0f, 1.0f};
constexpr Color kArrow{0.8f, 0.3f, 0.1f, 1.0f};

// 200x100 pixels, 10 pixels per metre, world origin at the image centre: the centre of
// pixel (i, j) is world ((i + 0.5 - 100) / 10, (50 - j - 0.5) / 10).
Camera test_camera() { return Camera::centered(vec2(0.0f, 0.0f), 10.0f, 200, 100); }

// A circle of radius 2 m at (-5, 0.05) with its orientation mark pointing +x, and an arrow
// along the centre line of row 49 from x = 1 m to x = 5.05 m (its tip in column 150).
void draw_known_scene(PrimitiveRenderer& draw) {
  draw.draw_solid_circle(vec2(-5.0f, 0.05f), 2.0f, vec2(1.0f, 0.0f), kFill, kOutline);
  draw.draw_arrow(vec2(1.0f, 0.05f), vec2(5.05f, 0.05f), kArrow);
}

// Every primitive kind at many sizes, angles and sub-pixel offsets, overlapping.
void draw_mixed_scene(PrimitiveRenderer& draw) {
  for (int i = 0; i < 24; ++i) {
    const float t = static_cast<float>(i);
    const vec2 at(-9.0f + 0.77f * t, -4.0f + 0.31f * static_cast<float>(i % 9));
    const vec2 along(std::cos(0.45f * t), std::sin(0.45f * t));
    draw.draw_solid_circle(at, 0.1f + 0.13f * static_cast<float>(i % 7), along, kFill, kOutline);
    draw.draw_segment(at, at + along * (0.2f + 0.4f * static_cast<float>(i % 5)), kArrow);
    draw.draw_arrow(at, at + along * (0.02f + 0.5f * static_cast<float>(i % 6)), kOutline);
    draw.draw_point(at + vec2(0.3f, 0.0f), 2.0f + static_cast<float>(i % 4), kArrow);
    draw.draw_text(at + vec2(0.0f, 0.5f), std::to_string(i), kOutline);
  }
  const vec2 hexagon[6] = {{2, 0}, {1, 1.7f}, {-1, 1.7f}, {-2, 0}, {-1, -1.7f}, {1, -1.7f}};
  draw.draw_solid_polygon(hexagon, 6, kFill, kOutline);
  const vec2 triangle[3] = {{5.0f, -4.0f}, {8.3f, -3.1f}, {6.2f, -0.4f}};
  draw.draw_solid_polygon(triangle, 3, kFill, kOutline);
  draw.draw_band({-3.0f, -4.2f}, {-1.2f, -3.1f}, 3.0f, kArrow);
  draw.draw_box_outline({3.1f, 0.2f}, {4.4f, 1.35f}, kArrow);
  draw.draw_segment({-9.5f, -4.5f}, {9.5f, 4.5f}, kOutline);  // long and diagonal
  // Centres just outside the frame: GL would drop such a point sprite whole.
  draw.draw_solid_circle({-10.2f, 1.0f}, 0.5f, {0, 1}, kFill, kOutline);
  draw.draw_text({9.5f, -5.3f}, "42", kOutline);
  draw.draw_screen_rect({3.5f, 60.25f}, {40.0f, 12.5f}, Color{0.1f, 0.2f, 0.9f, 0.5f});
  draw.draw_screen_text({2, 2}, "sprites\nand quads", kOutline, 2);
}

}  // namespace

TEST(RenderCamera, WorldToPixelIsYUpWithTopLeftOrigin) {
  const Camera camera = test_camera();
  EXPECT_EQ(camera.world_to_pixel(vec2(0.0f, 0.0f)), vec2(100.0f, 50.0f));
  EXPECT_EQ(camera.world_to_pixel(vec2(1.0f, 1.0f)), vec2(110.0f, 40.0f));
  EXPECT_EQ(camera.pixel_to_world(vec2(110.0f, 40.0f)), vec2(1.0f, 1.0f));
  const Aabb visible = camera.visible_bounds();
  EXPECT_EQ(visible.lower, vec2(-10.0f, -5.0f));
  EXPECT_EQ(visible.upper, vec2(10.0f, 5.0f));
}

TEST(RenderCamera, FitShowsBoundsWithMargin) {
  const Aabb bounds{vec2(-2.0f, 0.0f), vec2(6.0f, 2.0f)};
  const Camera camera = Camera::fit(bounds, 400, 300, 20.0f);
  EXPECT_FLOAT_EQ(camera.pixels_per_metre(), 45.0f);  // (400 - 40) / 8 limits
  EXPECT_EQ(camera.center(), vec2(2.0f, 1.0f));
  EXPECT_FLOAT_EQ(camera.world_to_pixel(bounds.lower).x, 20.0f);
  EXPECT_FLOAT_EQ(camera.world_to_pixel(bounds.upper).x, 380.0f);
  const Camera moved = camera.with_center(vec2(10.0f, 10.0f));
  EXPECT_EQ(moved.world_to_pixel(vec2(10.0f, 10.0f)), vec2(200.0f, 150.0f));
  EXPECT_FLOAT_EQ(moved.pixels_per_metre(), 45.0f);
}

TEST(RenderCamera, BadArgumentsAreErrors) {
  EXPECT_THROW(Camera::centered(vec2(0.0f), 0.0f, 10, 10), RenderError);
  EXPECT_THROW(Camera::centered(vec2(0.0f), 1.0f, 0, 10), RenderError);
  EXPECT_THROW(Camera::fit(Aabb{vec2(0.0f), vec2(1.0f)}, 30, 30, 20.0f), RenderError);
}

TEST(RenderContext, ZeroSizeIsAClearError) {
  try {
    create_offscreen_context(0, 600);
    FAIL() << "a 0x600 context was created";
  } catch (const RenderError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("0x600"), std::string::npos) << message;
    EXPECT_NE(message.find("OpenGL 3.3 core"), std::string::npos) << message;
    EXPECT_NE(message.find("llvmpipe"), std::string::npos) << message;
  }
}

TEST(RenderContext, ReportsLlvmpipeWithAtLeastGl33) {
  FrameRenderer renderer(64, 32);
  EXPECT_EQ(renderer.width(), 64);
  EXPECT_EQ(renderer.height(), 32);
  const std::string fingerprint = renderer.fingerprint();
  EXPECT_NE(fingerprint.find("llvmpipe"), std::string::npos) << fingerprint;
  EXPECT_NE(fingerprint.find("Core Profile"), std::string::npos) << fingerprint;
}

TEST(RenderPrimitives, CameraOfAnotherSizeIsRejected) {
  FrameRenderer renderer(64, 32);
  Frame frame;
  EXPECT_THROW(renderer.render_primitives(test_camera(), kWhite, [](PrimitiveRenderer&) {}, frame),
               RenderError);
}

TEST(RenderPrimitives, EmptyBatchIsTheOpaqueBackground) {
  FrameRenderer renderer(200, 100);
  Frame frame;
  const Color background{0.2f, 0.4f, 0.6f, 0.0f};  // alpha is ignored: frames are opaque
  renderer.render_primitives(test_camera(), background, [](PrimitiveRenderer&) {}, frame);
  ASSERT_EQ(frame.width, 200);
  ASSERT_EQ(frame.height, 100);
  for (int y = 0; y < frame.height; ++y) {
    for (int x = 0; x < frame.width; ++x) ASSERT_EQ(frame.pixel(x, y), to_pixel(background));
  }
}

TEST(RenderPrimitives, KnownColoursAtKnownPixels) {
  FrameRenderer renderer(200, 100);
  Frame frame;
  renderer.render_primitives(test_camera(), kWhite, draw_known_scene, frame);
  EXPECT_TRUE(frame.is_opaque());
  // Circle centre (-5, 0.05) is the centre of pixel (50, 49); the orientation mark runs
  // right from it, so sample the fill 5 pixels above and to the left of the centre.
  EXPECT_EQ(frame.pixel(50, 44), to_pixel(kFill));
  EXPECT_EQ(frame.pixel(45, 49), to_pixel(kFill));
  // The orientation mark and the outline are drawn in the outline colour.
  EXPECT_EQ(frame.pixel(60, 49), to_pixel(kOutline));
  EXPECT_EQ(frame.pixel(50, 29), to_pixel(kOutline));  // top of the rim: 2 m = 20 px above
  // Outside the circle, background.
  EXPECT_EQ(frame.pixel(50, 26), to_pixel(kWhite));
  EXPECT_EQ(frame.pixel(25, 49), to_pixel(kWhite));
  // The arrow: shaft, the head just behind the tip (column 150), nothing beyond it.
  EXPECT_EQ(frame.pixel(120, 49), to_pixel(kArrow));
  EXPECT_EQ(frame.pixel(148, 49), to_pixel(kArrow));
  EXPECT_EQ(frame.pixel(153, 49), to_pixel(kWhite));
  EXPECT_EQ(frame.pixel(120, 45), to_pixel(kWhite));
}

TEST(RenderPrimitives, EveryPrimitiveKindDraws) {
  FrameRenderer renderer(200, 100);
  Frame empty;
  renderer.render_primitives(test_camera(), kWhite, [](PrimitiveRenderer&) {}, empty);
  const auto differs = [&](const std::function<void(PrimitiveRenderer&)>& emit) {
    Frame frame;
    renderer.render_primitives(test_camera(), kWhite, emit, frame);
    return frame.hash() != empty.hash();
  };
  const vec2 box[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const vec2 pentagon[5] = {{0, 0}, {2, 0}, {2.5f, 1}, {1, 2}, {-0.5f, 1}};
  EXPECT_TRUE(differs([&](PrimitiveRenderer& d) { d.draw_solid_polygon(box, 4, kFill, kOutline); }));
  EXPECT_TRUE(differs([&](PrimitiveRenderer& d) { d.draw_solid_polygon(pentagon, 5, kFill, kOutline); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_segment({-3, 0}, {3, 1}, kArrow); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_band({-3, 0}, {3, 1}, 4.0f, kArrow); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_box_outline({-3, -1}, {3, 1}, kArrow); }));
  // More edges than one polygon primitive has: fill triangles and an outline segment per edge.
  vec2 decagon[10];
  for (int i = 0; i < 10; ++i) decagon[i] = 3.0f * vec2(std::cos(0.628f * i), std::sin(0.628f * i));
  EXPECT_TRUE(differs([&](PrimitiveRenderer& d) { d.draw_solid_polygon(decagon, 10, kFill, kOutline); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_point({0, 0}, 6.0f, kArrow); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_text({0, 0}, "42", kOutline); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_screen_rect({5, 5}, {10, 10}, kFill); }));
  EXPECT_TRUE(differs([](PrimitiveRenderer& d) { d.draw_screen_text({5, 5}, "HUD", kOutline, 1); }));
  // A zero-length arrow has no direction and draws nothing.
  EXPECT_FALSE(differs([](PrimitiveRenderer& d) { d.draw_arrow({1, 1}, {1, 1}, kArrow); }));
}

TEST(RenderPrimitives, ShapesAreFilledAndOutlinedWithTheirInsideClear) {
  FrameRenderer renderer(200, 100);
  Frame frame;
  renderer.render_primitives(test_camera(), kWhite, [](PrimitiveRenderer& draw) {
    // A square polygon whose edges run through the centres of columns 20 and 59 and rows 30
    // and 69, and a rectangle outline of the same size through columns 120 and 159.
    const vec2 square[4] = {{-7.95f, -1.95f}, {-4.05f, -1.95f}, {-4.05f, 1.95f}, {-7.95f, 1.95f}};
    draw.draw_solid_polygon(square, 4, kFill, kOutline);
    draw.draw_box_outline({2.05f, -1.95f}, {5.95f, 1.95f}, kArrow);
  }, frame);
  EXPECT_EQ(frame.pixel(40, 50), to_pixel(kFill));     // inside the polygon
  EXPECT_EQ(frame.pixel(20, 50), to_pixel(kOutline));  // on its left edge
  EXPECT_EQ(frame.pixel(40, 30), to_pixel(kOutline));  // on its top edge
  EXPECT_EQ(frame.pixel(17, 50), to_pixel(kWhite));
  EXPECT_EQ(frame.pixel(140, 50), to_pixel(kWhite));  // inside the outline: clear
  EXPECT_EQ(frame.pixel(120, 50), to_pixel(kArrow));
  EXPECT_EQ(frame.pixel(140, 69), to_pixel(kArrow));  // bottom edge
  EXPECT_EQ(frame.pixel(123, 50), to_pixel(kWhite));
}

TEST(RenderPrimitives, LaterLayersAreDrawnOverEarlierOnes) {
  // Within a layer the kinds go in a fixed order (polygons before boxes); a new layer goes
  // over everything before it whatever its kinds.
  const vec2 square[4] = {{-2, -2}, {2, -2}, {2, 2}, {-2, 2}};
  FrameRenderer renderer(200, 100);
  Frame one_layer;
  renderer.render_primitives(test_camera(), kWhite, [&](PrimitiveRenderer& draw) {
    draw.draw_screen_rect({90, 40}, {20, 20}, kArrow);
    draw.draw_solid_polygon(square, 4, kFill, kOutline);
  }, one_layer);
  EXPECT_EQ(one_layer.pixel(100, 50), to_pixel(kArrow));
  Frame two_layers;
  renderer.render_primitives(test_camera(), kWhite, [&](PrimitiveRenderer& draw) {
    draw.draw_screen_rect({90, 40}, {20, 20}, kArrow);
    draw.next_layer();
    draw.draw_solid_polygon(square, 4, kFill, kOutline);
  }, two_layers);
  EXPECT_EQ(two_layers.pixel(100, 50), to_pixel(kFill));
}

TEST(RenderPrimitives, SameInputTwiceIsBitIdentical) {
  FrameRenderer renderer(200, 100);
  Frame first;
  Frame second;
  renderer.render_primitives(test_camera(), kWhite, draw_known_scene, first);
  renderer.render_primitives(test_camera(), kWhite, [](PrimitiveRenderer&) {}, second);
  renderer.render_primitives(test_camera(), kWhite, draw_known_scene, second);
  EXPECT_EQ(first.rgba, second.rgba);
  // A second renderer (a new context) gives the same pixels too.
  FrameRenderer other(200, 100);
  Frame third;
  other.render_primitives(test_camera(), kWhite, draw_known_scene, third);
  EXPECT_EQ(first.rgba, third.rgba);
}

TEST(RenderPrimitives, PointSpritesAndQuadsGiveTheSamePixels) {
  // Small primitives are point sprites, large ones quads; the fragment stage measures each
  // pixel in the primitive's own frame, so forcing every primitive to a quad changes nothing.
  FrameRenderer sprites(200, 100);
  PrimitiveStyle quads_only;
  quads_only.max_point_sprite = 0.0f;
  FrameRenderer quads(200, 100, quads_only);
  Frame with_sprites;
  Frame with_quads;
  sprites.render_primitives(test_camera(), kWhite, draw_mixed_scene, with_sprites);
  quads.render_primitives(test_camera(), kWhite, draw_mixed_scene, with_quads);
  EXPECT_EQ(with_sprites.rgba, with_quads.rgba);
  Frame empty;
  sprites.render_primitives(test_camera(), kWhite, [](PrimitiveRenderer&) {}, empty);
  EXPECT_NE(with_sprites.hash(), empty.hash());
}

TEST(RenderPrimitives, TextCoversExactlyTheFontsRectangles) {
  // Each character is one primitive reading its glyph bitmap; the pixels must be those of
  // stb_easy_font's rectangles for the whole string (every printable character, two lines).
  std::string text;
  for (int code = 32; code < 127; ++code) {
    text += static_cast<char>(code);
    if (code == 79) text += '\n';
  }
  FrameRenderer renderer(400, 100);
  const Camera camera = Camera::centered(vec2(0.0f, 0.0f), 10.0f, 400, 100);
  for (const int scale : {1, 2}) {
    const vec2 top_left(3.0f, 5.0f);
    Frame frame;
    renderer.render_primitives(
        camera, kWhite, [&](PrimitiveRenderer& draw) { draw.draw_screen_text(top_left, text, kOutline, scale); },
        frame);
    std::vector<GlyphRect> rects;
    layout_text(text, rects);
    const float s = static_cast<float>(scale);
    int text_pixels = 0;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) {
        const float px = static_cast<float>(x) + 0.5f;
        const float py = static_cast<float>(y) + 0.5f;
        bool inside = false;
        for (const GlyphRect& r : rects) {
          inside = inside || (px > top_left.x + r.left * s && px < top_left.x + r.right * s &&
                              py > top_left.y + r.top * s && py < top_left.y + r.bottom * s);
        }
        text_pixels += inside ? 1 : 0;
        ASSERT_EQ(frame.pixel(x, y), to_pixel(inside ? kOutline : kWhite)) << "scale " << scale << " at " << x << "," << y;
      }
    }
    EXPECT_GT(text_pixels, 500 * scale * scale);
  }
}

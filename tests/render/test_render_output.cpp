// Frames out: PNG round trips through stb_image, atomic writes that leave nothing behind on
// failure and the frame-sequence writer.
#include "render/frame_renderer.h"
#include "render/frame_writer.h"
#include "render/render_error.h"
#include "image/error.h"
#include "image/png.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace impulse2d;
using namespace impulse2d::render;
namespace support = impulse2d::render::testing;
namespace fs = std::filesystem;

namespace {

Frame rendered_frame() {
  const World world = support::make_overlay_scene(20);
  FrameRenderer renderer(240, 160);
  FrameOptions options;
  options.draw.flags = draw_all;
  return renderer.render(world, Camera::fit(world_bounds(world), 240, 160), options, impulse2d::render::testing::hud("png", 20));
}

int count_entries(const fs::path& directory) {
  int count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(directory)) ++count;
  return count;
}

}  // namespace

TEST(RenderPng, RoundTripThroughStbImageIsExactAndOpaque) {
  const Frame frame = rendered_frame();
  ASSERT_TRUE(frame.is_opaque());
  for (const image::PngCompression encoding : {image::PngCompression::Fast, image::PngCompression::Small}) {
    const std::vector<std::uint8_t> png = image::encode_png(frame, encoding);
    Frame decoded;
    ASSERT_TRUE(support::decode_png(png, decoded));
    EXPECT_EQ(decoded.width, frame.width);
    EXPECT_EQ(decoded.height, frame.height);
    EXPECT_TRUE(decoded.is_opaque());
    EXPECT_EQ(decoded.rgba, frame.rgba) << "encoding " << static_cast<int>(encoding);
    EXPECT_EQ(decoded.hash(), frame.hash());
  }
}

TEST(RenderPng, OpaqueImagesAreWrittenAsRgbOthersAsRgbaBothExactly) {
  // Every byte value in every channel, rows of an odd width; the PNG's IHDR colour type is the
  // byte at offset 25 (8 signature, 8 chunk header, 4 width, 4 height, 1 depth).
  image::Image picture;
  picture.resize(7, 5);
  for (std::size_t byte = 0; byte < picture.rgba.size(); ++byte) {
    picture.rgba[byte] = (byte % 4 == 3) ? 255 : static_cast<std::uint8_t>(byte * 37 % 256);
  }
  picture.text["Scene"] = "png";
  constexpr std::size_t colour_type_offset = 25;
  for (const image::PngCompression encoding : {image::PngCompression::Fast, image::PngCompression::Small}) {
    const std::vector<std::uint8_t> opaque_png = image::encode_png(picture, encoding);
    ASSERT_GT(opaque_png.size(), colour_type_offset);
    EXPECT_EQ(opaque_png[colour_type_offset], 2) << "an opaque image is written as RGB";
    const image::Image opaque_decoded = image::decode_png(opaque_png, "opaque.png");
    EXPECT_EQ(opaque_decoded.rgba, picture.rgba);
    EXPECT_EQ(opaque_decoded.text, picture.text);
    // One alpha below 255, in the first pixel and then in the last, keeps the alpha channel.
    for (const std::size_t pixel : {std::size_t{0}, picture.pixel_count() - 1}) {
      image::Image translucent = picture;
      translucent.rgba[pixel * 4 + 3] = 254;
      const std::vector<std::uint8_t> png = image::encode_png(translucent, encoding);
      EXPECT_EQ(png[colour_type_offset], 6) << "pixel " << pixel;
      EXPECT_EQ(image::decode_png(png, "translucent.png").rgba, translucent.rgba) << "pixel " << pixel;
    }
  }
}

TEST(RenderPng, TopRowOfTheFileIsTheTopOfTheScene) {
  // A red band at the top of the picture (world y up) must be the first rows of the PNG.
  FrameRenderer renderer(40, 20);
  Frame frame;
  renderer.render_primitives(Camera::centered(vec2(0.0f), 1.0f, 40, 20), Color{1, 1, 1, 1},
                             [](PrimitiveRenderer& draw) {
                               const vec2 band[4] = {{-20, 5}, {20, 5}, {20, 10}, {-20, 10}};
                               draw.draw_solid_polygon(band, 4, Color{1, 0, 0, 1}, Color{1, 0, 0, 1});
                             },
                             frame);
  Frame decoded;
  ASSERT_TRUE(support::decode_png(image::encode_png(frame), decoded));
  EXPECT_EQ(decoded.pixel(20, 1), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(decoded.pixel(20, 18), (Pixel{255, 255, 255, 255}));
}

TEST(RenderPng, WritePngReplacesTheFileAtomically) {
  const fs::path directory = support::make_temporary_directory("render-png");
  const Frame frame = rendered_frame();
  const fs::path path = directory / "frame.png";
  image::save_png(path, frame, image::PngCompression::Fast);
  image::save_png(path, frame, image::PngCompression::Small);
  Frame decoded;
  ASSERT_TRUE(support::decode_png(support::read_file(path.string()), decoded));
  EXPECT_EQ(decoded.rgba, frame.rgba);
  EXPECT_EQ(count_entries(directory), 1);  // no temporary file left
  fs::remove_all(directory);
}

TEST(RenderPng, BadInputIsAClearErrorAndLeavesNoFile) {
  const fs::path directory = support::make_temporary_directory("render-bad");
  Frame empty;
  EXPECT_THROW(image::encode_png(empty), image::ImageError);
  EXPECT_THROW(image::save_png(directory / "empty.png", empty), image::ImageError);
  Frame inconsistent;
  inconsistent.width = 4;
  inconsistent.height = 4;
  inconsistent.rgba.resize(10);
  EXPECT_THROW(image::encode_png(inconsistent), image::ImageError);
  // A directory that cannot exist: its parent is a regular file.
  const fs::path blocker = directory / "not_a_directory";
  std::ofstream(blocker) << "x";
  try {
    image::save_png(blocker / "frame.png", rendered_frame());
    FAIL() << "writing under a regular file succeeded";
  } catch (const image::ImageError& error) {
    EXPECT_NE(std::string(error.what()).find((blocker / "frame.png").string()), std::string::npos) << error.what();
  }
  EXPECT_EQ(count_entries(directory), 1);  // only the blocker
  fs::remove_all(directory);
}

TEST(RenderFrameWriter, WritesNamedFramesInAnyWorkerOrder) {
  const fs::path directory = support::make_temporary_directory("render-writer");
  const Frame frame = rendered_frame();
  {
    FrameWriterOptions options;
    options.directory = directory / "out";
    options.scene_name = "pile";
    options.worker_threads = 2;
    options.queue_capacity = 2;
    AsyncFrameWriter writer(options);
    EXPECT_EQ(writer.path_for(7), directory / "out" / "pile_00007.png");
    for (const std::int64_t number : {0, 5, 10, 15, 123456}) {
      Frame copy = writer.take_spare_frame();
      copy = frame;
      writer.submit(number, std::move(copy));
    }
    writer.finish();
    const FrameWriterStats stats = writer.stats();
    EXPECT_EQ(stats.frames_written, 5);
    EXPECT_GT(stats.bytes_written, 0u);
    EXPECT_THROW(writer.submit(20, frame), RenderError);
  }
  for (const char* name : {"pile_00000.png", "pile_00005.png", "pile_00010.png", "pile_00015.png", "pile_123456.png"}) {
    Frame decoded;
    ASSERT_TRUE(support::decode_png(support::read_file((directory / "out" / name).string()), decoded)) << name;
    EXPECT_EQ(decoded.rgba, frame.rgba) << name;
  }
  EXPECT_EQ(count_entries(directory / "out"), 5);
  fs::remove_all(directory);
}

TEST(RenderFrameWriter, UnwritableDirectoryAndBadOptionsAreClearErrors) {
  const fs::path directory = support::make_temporary_directory("render-writer-bad");
  const fs::path blocker = directory / "file";
  std::ofstream(blocker) << "x";
  FrameWriterOptions options;
  options.directory = blocker / "frames";
  options.scene_name = "scene";
  try {
    AsyncFrameWriter writer(options);
    FAIL() << "a writer under a regular file was created";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find(options.directory.string()), std::string::npos) << error.what();
  }
  options.directory = directory / "frames";
  options.scene_name = "a/b";
  EXPECT_THROW(AsyncFrameWriter{options}, RenderError);
  options.scene_name = "scene";
  options.worker_threads = 0;
  EXPECT_THROW(AsyncFrameWriter{options}, RenderError);
  options.worker_threads = 1;
  AsyncFrameWriter writer(options);
  EXPECT_THROW(writer.submit(0, Frame{}), RenderError);
  EXPECT_THROW(writer.submit(-1, rendered_frame()), RenderError);
  writer.finish();
  EXPECT_EQ(count_entries(directory / "frames"), 0);
  fs::remove_all(directory);
}

TEST(RenderFrameWriter, FailedWriteIsReportedAndLeavesNoPartialFile) {
  const fs::path directory = support::make_temporary_directory("render-writer-fail");
  FrameWriterOptions options;
  options.directory = directory;
  options.scene_name = "scene";
  AsyncFrameWriter writer(options);
  // Occupy frame 3's file name with a directory, so the rename onto it fails.
  fs::create_directory(writer.path_for(3));
  writer.submit(3, rendered_frame());
  EXPECT_THROW(writer.finish(), RenderError);
  EXPECT_EQ(count_entries(directory), 1);  // the blocking directory, no temporary file
  fs::remove_all(directory);
}

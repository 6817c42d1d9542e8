// Frames must not depend on how many threads llvmpipe rasterises with. llvmpipe reads
// LP_NUM_THREADS once, when the first context of a process is created, so each setting
// runs in a fresh child process (this binary, filtered to the child test below).
#include "render/driver_quirks.h"
#include "render/frame_renderer.h"
#include "image/png.h"
#include "render/render_error.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <dirent.h>

#include <cstdlib>
#include <fstream>
#include <string>

using namespace impulse2d;
using namespace impulse2d::render;
namespace support = impulse2d::render::testing;

namespace {

constexpr const char* kOutputVariable = "IMPULSE2D_RENDER_CHILD_OUTPUT";

// Threads of this process whose name starts with "llvmpipe-" (llvmpipe's rasterisers).
int llvmpipe_thread_count() {
  int count = 0;
  DIR* tasks = opendir("/proc/self/task");
  if (tasks == nullptr) return -1;
  while (const dirent* entry = readdir(tasks)) {
    if (entry->d_name[0] == '.') continue;
    std::ifstream comm(std::string("/proc/self/task/") + entry->d_name + "/comm");
    std::string name;
    std::getline(comm, name);
    if (name.rfind("llvmpipe-", 0) == 0) ++count;
  }
  closedir(tasks);
  return count;
}

}  // namespace

// Runs only as a child: renders the overlay scene and writes the raw RGBA to the file named
// by IMPULSE2D_RENDER_CHILD_OUTPUT, followed by the llvmpipe thread count on its own line
// in "<path>.threads".
TEST(RenderThreadsChild, WriteFrame) {
  const char* output = std::getenv(kOutputVariable);
  if (output == nullptr) GTEST_SKIP() << "runs only as the child of RenderThreads tests";
  const World world = support::make_overlay_scene(30);
  FrameRenderer renderer(400, 240);
  FrameOptions options;
  options.draw.flags = draw_all;
  const Frame frame =
      renderer.render(world, Camera::fit(world_bounds(world), 400, 240), options, impulse2d::render::testing::hud("threads", 30));
  std::ofstream(output, std::ios::binary)
      .write(reinterpret_cast<const char*>(frame.rgba.data()), static_cast<std::streamsize>(frame.rgba.size()));
  std::ofstream(std::string(output) + ".threads") << llvmpipe_thread_count() << "\n";
}

TEST(RenderThreads, OneTwoAndFourThreadsGiveIdenticalFrames) {
  const std::string directory = support::make_temporary_directory("render-threads");
  ASSERT_FALSE(directory.empty());
  std::vector<std::uint8_t> reference;
  for (const int threads : {1, 2, 4}) {
    const std::string output = directory + "/frame_" + std::to_string(threads) + ".rgba";
    const int status = support::run_self("RenderThreadsChild.WriteFrame",
                                         {{"LP_NUM_THREADS", std::to_string(threads)}, {kOutputVariable, output}});
    ASSERT_EQ(status, 0) << "child with LP_NUM_THREADS=" << threads << " failed";
    int observed = -1;
    std::ifstream(output + ".threads") >> observed;
    EXPECT_EQ(observed, threads) << "llvmpipe did not honour LP_NUM_THREADS=" << threads;
    const std::vector<std::uint8_t> pixels = support::read_file(output);
    ASSERT_EQ(pixels.size(), 400u * 240u * 4u);
    if (reference.empty()) {
      reference = pixels;
    } else {
      EXPECT_TRUE(pixels == reference) << "LP_NUM_THREADS=" << threads << " differs from 1 thread";
    }
    std::remove(output.c_str());
    std::remove((output + ".threads").c_str());
  }
  std::remove(directory.c_str());
}

// Runs only as a child with LP_NATIVE_VECTOR_WIDTH=128: llvmpipe at 128-bit vectors would
// abort inside the driver on the first frame (driver_quirks.h), so the renderer must refuse
// before drawing, with a message that names the variable.
TEST(RenderVectorWidthChild, RefusesWithAMessage) {
  if (std::getenv("LP_NATIVE_VECTOR_WIDTH") == nullptr) GTEST_SKIP() << "runs only as a child";
  try {
    FrameRenderer renderer(320, 240);
    const World world = support::make_overlay_scene(30);
    FrameOptions options;
    options.draw.flags = draw_all;
    renderer.render(world, Camera::fit(world_bounds(world), 320, 240), options, support::hud("width", 30));
    FAIL() << "rendered at 128-bit vectors";
  } catch (const RenderError& error) {
    EXPECT_NE(std::string(error.what()).find("LP_NATIVE_VECTOR_WIDTH=128 is set"), std::string::npos)
        << error.what();
  }
}

TEST(RenderThreads, NativeVectorWidth128IsRefusedNotAnAbort) {
  const int status = support::run_self("RenderVectorWidthChild.RefusesWithAMessage",
                                       {{"LP_NATIVE_VECTOR_WIDTH", "128"}});
  EXPECT_EQ(status, 0) << "the child aborted or rendered (status " << status << ")";
}

TEST(RenderThreads, OnlyLlvmpipeAt128BitVectorsIsRefused) {
  EXPECT_THROW(check_driver("llvmpipe (LLVM 15.0.6, 128 bits)"), RenderError);
  EXPECT_NO_THROW(check_driver("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_NO_THROW(check_driver("softpipe"));
  EXPECT_NO_THROW(check_driver("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
}

// The two offscreen backends, OSMesa and EGL surfaceless, chosen at run time: the same scene
// must give bit-identical frames on both (both are Mesa's llvmpipe here), each must say which
// renderer it drew with, and a backend name is checked wherever it comes from.
#include "render/frame_renderer.h"
#include "render/offscreen_backend.h"
#include "render/offscreen_context.h"
#include "render/render_error.h"
#include "tests/support/test_render_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace impulse2d;
using namespace impulse2d::render;
namespace support = impulse2d::render::testing;

namespace {

Frame render_on(Backend backend, const World& world, std::string* fingerprint) {
  FrameRenderer renderer(create_offscreen_context(320, 200, backend));
  *fingerprint = renderer.fingerprint();
  FrameOptions options;
  options.draw.flags = draw_all;
  return renderer.render(world, Camera::fit(world_bounds(world), 320, 200), options,
                         support::hud("backends", 40));
}

}  // namespace

TEST(RenderBackends, OsmesaAndEglFramesAreBitIdentical) {
  if (!backend_available(Backend::OSMesa)) GTEST_SKIP() << "built without OSMesa";
  const World world = support::make_overlay_scene(40);
  std::string osmesa_fingerprint;
  std::string egl_fingerprint;
  const Frame osmesa = render_on(Backend::OSMesa, world, &osmesa_fingerprint);
  const Frame egl = render_on(Backend::Egl, world, &egl_fingerprint);
  EXPECT_NE(osmesa_fingerprint.find("llvmpipe"), std::string::npos) << osmesa_fingerprint;
  EXPECT_NE(egl_fingerprint.find("llvmpipe"), std::string::npos) << egl_fingerprint;
  ASSERT_EQ(osmesa.width, egl.width);
  ASSERT_EQ(osmesa.height, egl.height);
  int differing = 0;
  int drawn = 0;  // pixels unlike the top-left corner's background: a blank frame matches trivially
  for (int y = 0; y < osmesa.height; ++y) {
    for (int x = 0; x < osmesa.width; ++x) {
      if (osmesa.pixel(x, y) != egl.pixel(x, y)) ++differing;
      if (osmesa.pixel(x, y) != osmesa.pixel(0, 0)) ++drawn;
    }
  }
  EXPECT_EQ(differing, 0) << "pixels that differ between OSMesa and EGL";
  EXPECT_GT(drawn, 2000) << "the scene left the frame nearly blank";
}

TEST(RenderBackends, BothRefuseBadSizesNamingTheBackend) {
  for (const Backend backend : {Backend::OSMesa, Backend::Egl}) {
    try {
      create_offscreen_context(0, 10, backend);
      FAIL() << backend_name(backend) << " accepted a 0x10 context";
    } catch (const RenderError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(backend == Backend::Egl ? "EGL" : "OSMesa"), std::string::npos)
          << message;
      EXPECT_NE(message.find("0x10"), std::string::npos) << message;
    }
  }
}

TEST(RenderBackends, NamesAreParsedAndBadOnesNamed) {
  EXPECT_EQ(parse_backend("osmesa", "test"), Backend::OSMesa);
  EXPECT_EQ(parse_backend("egl", "test"), Backend::Egl);
  EXPECT_STREQ(backend_name(Backend::Egl), "egl");
  EXPECT_STREQ(backend_name(Backend::OSMesa), "osmesa");
  try {
    parse_backend("vulkan", "--backend");
    FAIL() << "vulkan was accepted";
  } catch (const RenderError& error) {
    EXPECT_EQ(std::string(error.what()),
              "--backend: unknown renderer backend 'vulkan' (use osmesa or egl)");
  }
}

// The environment variable is read when no backend was set in the process; this test runs
// before any set_default_backend call of this binary (none of the other suites makes one).
TEST(RenderBackends, EnvironmentVariableChoosesTheDefault) {
  ASSERT_EQ(setenv("IMPULSE2D_BACKEND", "egl", 1), 0);
  EXPECT_EQ(default_backend(), Backend::Egl);
  ASSERT_EQ(setenv("IMPULSE2D_BACKEND", "bogus", 1), 0);
  EXPECT_THROW(default_backend(), RenderError);
  ASSERT_EQ(unsetenv("IMPULSE2D_BACKEND"), 0);
  EXPECT_EQ(default_backend(),
            backend_available(Backend::OSMesa) ? Backend::OSMesa : Backend::Egl);
}

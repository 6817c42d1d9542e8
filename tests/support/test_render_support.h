#pragma once
// Helpers shared by the renderer suites: PNG decoding (stb_image), colour conversion, a
// small scene with every overlay present, and running this test binary as a child process.

#include "core/world.h"
#include "render/frame.h"
#include "render/hud.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace impulse2d::render::testing {

/// HUD information with a scene name and frame number and no wall-clock figures.
inline HudInfo hud(const std::string& scene_name, std::int64_t frame) {
  HudInfo info;
  info.scene_name = scene_name;
  info.step = frame;
  return info;
}

/// Decodes PNG bytes to a top-down RGBA frame with stb_image. Returns false on failure.
bool decode_png(const std::vector<std::uint8_t>& png, Frame& frame);

/// The 8-bit pixel the renderer writes for an opaque colour.
Pixel to_pixel(Color color);

/// A scene with a static ground and a ramp, a resting stack, a sliding box, a falling
/// circle and a sleeping polygon, stepped `steps` times: contacts, impulses (normal and
/// friction), penetration, velocities and a sleeping body are all present.
World make_overlay_scene(int steps);

/// Runs this test binary again with `--gtest_filter=<test_filter>` and the extra
/// environment `variables`; returns its exit status (-1 when it could not start).
int run_self(const std::string& test_filter, const std::map<std::string, std::string>& variables);

/// Reads a whole file; empty when it does not exist.
std::vector<std::uint8_t> read_file(const std::string& path);

/// A fresh empty directory under the system temporary directory.
std::string make_temporary_directory(const std::string& tag);

}  // namespace impulse2d::render::testing

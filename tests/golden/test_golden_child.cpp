/// @file test_golden_child.cpp
/// The child side (a test that does its work only when the parent's variables are set) and
/// the parent side of `child_process_producer`.
#include "tests/golden/test_golden_child.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "tests/support/test_render_support.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "image/image.h"
#include "image/png.h"
#include "golden/scenes/golden_catalog.h"
#include "golden/scenes/scene_frame.h"

namespace impulse2d::golden::testing {

namespace {

namespace fs = std::filesystem;

constexpr const char* kGoldenVariable = "IMPULSE2D_GOLDEN_CHILD_GOLDEN";
constexpr const char* kOutputVariable = "IMPULSE2D_GOLDEN_CHILD_OUTPUT";
constexpr const char* kVariantVariable = "IMPULSE2D_GOLDEN_CHILD_VARIANT";

// Runs only as a child: renders the golden named by IMPULSE2D_GOLDEN_CHILD_GOLDEN (with the
// variant named by IMPULSE2D_GOLDEN_CHILD_VARIANT) into the PNG named by
// IMPULSE2D_GOLDEN_CHILD_OUTPUT, and its state hash into "<output>.hash".
TEST(GoldenChild, WriteFrame) {
  const char* id = std::getenv(kGoldenVariable);
  const char* output = std::getenv(kOutputVariable);
  const char* variant = std::getenv(kVariantVariable);
  if (id == nullptr || output == nullptr) GTEST_SKIP() << "runs only as a child";
  const GoldenSpec* spec = find_golden(id);
  ASSERT_NE(spec, nullptr) << id;
  const ChildVariant chosen = variant != nullptr && std::string(variant) == "pid_gravity"
                                  ? ChildVariant::ProcessDependentGravity
                                  : ChildVariant::None;
  const ProducedFrame frame =
      produce_scene_frame(*spec, shared_golden_renderer(), child_variant(chosen));
  image::save_png(output, frame.image);
  image::write_text_file_atomically(std::string(output) + ".hash", image::to_hex_hash(frame.state_hash));
}

}  // namespace

SceneVariant child_variant(ChildVariant variant) {
  if (variant == ChildVariant::None) return nullptr;
  return [](demos::Scene& scene) {
    // 10 um/s^2 per pid: distinct pids give distinct floats near 9.81.
    scene.settings.gravity.y -= 1e-5f * static_cast<float>(::getpid() % 100000);
  };
}

FrameProducer child_process_producer(const std::string& id,
                                     const std::map<std::string, std::string>& variables,
                                     ChildVariant variant) {
  return [id, variables, variant] {
    const fs::path directory = render::testing::make_temporary_directory("golden-child");
    const fs::path output = directory / "frame.png";
    std::map<std::string, std::string> environment = variables;
    environment[kGoldenVariable] = id;
    environment[kOutputVariable] = output.string();
    if (variant == ChildVariant::ProcessDependentGravity) environment[kVariantVariable] = "pid_gravity";
    const int status = render::testing::run_self("GoldenChild.WriteFrame", environment);
    if (status != 0 || !fs::exists(output)) {
      fs::remove_all(directory);
      throw std::runtime_error("golden '" + id + "': the child process failed (status " +
                               std::to_string(status) + ")");
    }
    ProducedFrame frame;
    frame.image = image::load_png(output);
    const auto hash = image::parse_hex_hash(image::read_text_file(output.string() + ".hash"));
    fs::remove_all(directory);
    if (!hash) throw std::runtime_error("golden '" + id + "': the child wrote no state hash");
    frame.state_hash = *hash;
    return frame;
  };
}

}  // namespace impulse2d::golden::testing

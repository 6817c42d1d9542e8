/// @file test_image_diff.cpp
/// The golden-image library on synthetic images: exact match, each tolerance layer, size
/// and alpha differences, failure classes, sidecars, update modes, artifacts, the HTML
/// report and the promote script.

#include "tests/golden/test_golden_environment.h"
#include "tests/golden/test_golden_temp_dir.h"
#include "golden/artifacts.h"
#include "golden/base64.h"
#include "golden/body_drift.h"
#include "golden/compare.h"
#include "golden/diff_images.h"
#include "golden/error.h"
#include "golden/failure.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "image/image.h"
#include "image/png.h"
#include "golden/inventory.h"
#include "golden/report.h"
#include "golden/sidecar.h"
#include "golden/tolerance.h"
#include "golden/update_mode.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace impulse2d::golden {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr image::Rgba kBackground{30, 60, 90, 255};

using testing::TempDir;

/// Adds `delta` to the red channel of every pixel in the square [x, x+size) x [y, y+size).
void shift_red(image::Image& image, int x, int y, int size, int delta) {
  for (int row = y; row < y + size; ++row) {
    for (int column = x; column < x + size; ++column) {
      image::Rgba colour = image.pixel(column, row);
      colour.r = static_cast<std::uint8_t>(colour.r + delta);
      image.set_pixel(column, row, colour);
    }
  }
}

/// The message of `function`'s GoldenError; fails the test when it does not throw one.
template <typename Function>
std::string error_of(Function function) {
  try {
    function();
  } catch (const GoldenError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected a GoldenError";
  return "";
}

Sidecar example_sidecar() {
  Sidecar sidecar;
  sidecar.scene = "circles";
  sidecar.frame = 120;
  sidecar.width = 64;
  sidecar.height = 48;
  sidecar.state_hash = 0x0123456789abcdefull;
  sidecar.renderer = {"llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Compatibility Profile) Mesa"};
  sidecar.bodies = {{"ground", 0.0, -1.0, 0.0}, {"ball 1", 0.25, 2.5, 0.125}};
  return sidecar;
}

// ---- image -------------------------------------------------------------------------------

TEST(GoldenImage, HashCoversSizeAndPixels) {
  const image::Image a = image::make_image(8, 2, kBackground);
  const image::Image b = image::make_image(2, 8, kBackground);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_NE(a.hash(), b.hash());
  image::Image c = a;
  c.set_pixel(7, 1, image::Rgba{30, 60, 90, 254});
  EXPECT_NE(a.hash(), c.hash());
  EXPECT_EQ(a.hash(), image::make_image(8, 2, kBackground).hash());
}

TEST(GoldenImage, PngRoundTripKeepsEveryByteAndLeavesNoTemporaryFile) {
  TempDir dir;
  image::Image image = image::make_image(17, 9, kBackground);
  image.set_pixel(3, 4, image::Rgba{255, 0, 128, 0});
  image.set_pixel(16, 8, image::Rgba{1, 2, 3, 77});
  const fs::path file = dir.path() / "nested" / "image.png";
  image::save_png(file, image);
  const image::Image loaded = image::load_png(file);
  EXPECT_EQ(loaded.width, 17);
  EXPECT_EQ(loaded.height, 9);
  EXPECT_EQ(loaded.hash(), image.hash());
  int files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(file.parent_path())) ++files;
  EXPECT_EQ(files, 1);
}

TEST(GoldenImage, LoadErrorsNameTheFile) {
  TempDir dir;
  const fs::path missing = dir.path() / "missing.png";
  EXPECT_NE(error_of([&] { image::load_png(missing); }).find("missing.png"), std::string::npos);
  const fs::path garbage = dir.path() / "garbage.png";
  image::write_text_file_atomically(garbage, "not a png");
  const std::string message = error_of([&] { image::load_png(garbage); });
  EXPECT_NE(message.find("cannot decode PNG"), std::string::npos) << message;
  EXPECT_NE(message.find("garbage.png"), std::string::npos) << message;
}

TEST(GoldenHexHash, RoundTripsAndRejectsMalformedText) {
  EXPECT_EQ(image::to_hex_hash(0x00000000000000ffull), "00000000000000ff");
  EXPECT_EQ(image::parse_hex_hash("0123456789ABCDEF"), 0x0123456789abcdefull);
  EXPECT_EQ(image::parse_hex_hash(image::to_hex_hash(0xfedcba9876543210ull)), 0xfedcba9876543210ull);
  EXPECT_FALSE(image::parse_hex_hash("123"));
  EXPECT_FALSE(image::parse_hex_hash("0x23456789abcdef"));
  EXPECT_FALSE(image::parse_hex_hash("0123456789abcdeg"));
}

TEST(GoldenBase64, MatchesRfc4648Vectors) {
  auto encode = [](const std::string& text) {
    return base64_encode(std::vector<std::uint8_t>(text.begin(), text.end()));
  };
  EXPECT_EQ(encode(""), "");
  EXPECT_EQ(encode("f"), "Zg==");
  EXPECT_EQ(encode("fo"), "Zm8=");
  EXPECT_EQ(encode("foo"), "Zm9v");
  EXPECT_EQ(encode("foob"), "Zm9vYg==");
  EXPECT_EQ(encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(encode("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64_encode({0xfb, 0xff}), "+/8=");
}

// ---- comparison ----------------------------------------------------------------------------

TEST(GoldenCompare, IdenticalImagesAreAnExactMatchWithoutMetrics) {
  const image::Image golden = image::make_image(32, 32, kBackground);
  const CompareResult result = compare_images(golden, image::make_image(32, 32, kBackground));
  EXPECT_EQ(result.outcome, CompareOutcome::ExactMatch);
  EXPECT_TRUE(result.passed());
  EXPECT_EQ(result.expected_hash, result.actual_hash);
  EXPECT_EQ(result.metrics.changed_pixels, 0);
  EXPECT_NE(result.message().find("exact match"), std::string::npos);
}

TEST(GoldenCompare, OnePixelOffByOnePassesWithinChannelTolerance) {
  const image::Image golden = image::make_image(32, 32, kBackground);
  image::Image actual = golden;
  shift_red(actual, 5, 7, 1, 1);
  Tolerance tolerance;
  tolerance.max_channel_delta = 1;
  tolerance.origin = "test";
  const CompareResult result = compare_images(golden, actual, tolerance);
  EXPECT_EQ(result.outcome, CompareOutcome::WithinTolerance);
  EXPECT_TRUE(result.passed());
  EXPECT_EQ(result.metrics.changed_pixels, 1);
  EXPECT_EQ(result.metrics.differing_pixels, 0);
  EXPECT_EQ(result.metrics.max_channel_delta, 1);
  EXPECT_TRUE(result.violations.empty());
}

TEST(GoldenCompare, OnePixelBeyondToleranceFailsWhenStrict) {
  const image::Image golden = image::make_image(32, 32, kBackground);
  image::Image actual = golden;
  shift_red(actual, 5, 7, 1, 1);
  const CompareResult result = compare_images(golden, actual);
  EXPECT_EQ(result.outcome, CompareOutcome::ExceedsTolerance);
  EXPECT_FALSE(result.passed());
  EXPECT_EQ(result.metrics.differing_pixels, 1);
  EXPECT_EQ(result.metrics.differing_box.min_x, 5);
  EXPECT_EQ(result.metrics.differing_box.min_y, 7);
  ASSERT_EQ(result.violations.size(), 3u);  // count, ratio and window all have limit 0
  EXPECT_NE(result.message().find("1 differing pixels; limit 0 (strict default)"),
            std::string::npos)
      << result.message();

  Tolerance loose_delta;
  loose_delta.max_channel_delta = 1;
  shift_red(actual, 5, 7, 1, 1);  // now off by 2
  EXPECT_EQ(compare_images(golden, actual, loose_delta).outcome,
            CompareOutcome::ExceedsTolerance);
}

/// Limits that allow 100 differing pixels anywhere (1% of the image) but at most 4 in any
/// 8x8 window, as a sidecar would set them.
Tolerance cluster_sensitive_tolerance() {
  return tolerance_from_json(json{{"max_differing_pixels", 100},
                                  {"max_differing_ratio", 0.01},
                                  {"window_size", 8},
                                  {"max_window_pixels", 4}},
                             "sidecar 'circles/start.json'");
}

TEST(GoldenCompare, FiveByFiveClusterFailsWindowRuleThoughTotalsAreWithinLimits) {
  for (int side : {256, 1024}) {  // the rule does not loosen as the image grows
    const image::Image golden = image::make_image(side, side, kBackground);
    image::Image actual = golden;
    shift_red(actual, 40, 32, 5, 50);
    const CompareResult result = compare_images(golden, actual, cluster_sensitive_tolerance());
    EXPECT_EQ(result.outcome, CompareOutcome::ExceedsTolerance) << side;
    EXPECT_EQ(result.metrics.differing_pixels, 25);
    EXPECT_LT(result.metrics.differing_ratio, 0.01);
    ASSERT_EQ(result.violations.size(), 1u);
    const RuleViolation& violation = result.violations[0];
    EXPECT_EQ(violation.rule, ToleranceRule::WindowDensity);
    EXPECT_EQ(violation.measured, 25.0);
    EXPECT_EQ(violation.limit, 4.0);
    // The window holding the cluster: its top-left lies within 3 pixels of the cluster's.
    EXPECT_GE(result.metrics.worst_window_x, 37);
    EXPECT_LE(result.metrics.worst_window_x, 40);
    EXPECT_GE(result.metrics.worst_window_y, 29);
    EXPECT_LE(result.metrics.worst_window_y, 32);
    EXPECT_NE(violation.text.find("worst 8x8 window"), std::string::npos);
    EXPECT_NE(violation.text.find("has 25 differing pixels; limit 4 (override from sidecar "
                                  "'circles/start.json')"),
              std::string::npos)
        << violation.text;
    EXPECT_NE(result.message().find("changes within (40,32)-(44,36)"), std::string::npos)
        << result.message();
  }
}

TEST(GoldenCompare, SameCountScatteredPassesWindowRule) {
  const image::Image golden = image::make_image(256, 256, kBackground);
  image::Image actual = golden;
  for (int i = 0; i < 25; ++i) shift_red(actual, (i % 5) * 16, (i / 5) * 16, 1, 50);
  const CompareResult result = compare_images(golden, actual, cluster_sensitive_tolerance());
  EXPECT_EQ(result.outcome, CompareOutcome::WithinTolerance) << result.message();
  EXPECT_EQ(result.metrics.differing_pixels, 25);
  EXPECT_EQ(result.metrics.worst_window_pixels, 1);
  EXPECT_NE(result.message().find("override from sidecar 'circles/start.json'"),
            std::string::npos);
}

TEST(GoldenCompare, WindowIsClampedToSmallImages) {
  const image::Image golden = image::make_image(4, 3, kBackground);
  image::Image actual = golden;
  shift_red(actual, 0, 0, 3, 9);
  const CompareResult result = compare_images(golden, actual);
  EXPECT_EQ(result.metrics.window_width, 4);
  EXPECT_EQ(result.metrics.window_height, 3);
  EXPECT_EQ(result.metrics.worst_window_pixels, 9);
}

TEST(GoldenCompare, RejectsMalformedPixelBuffers) {
  image::Image broken = image::make_image(4, 4, kBackground);
  broken.rgba.pop_back();
  const std::string message =
      error_of([&] { compare_images(image::make_image(4, 4, kBackground), broken); });
  EXPECT_NE(message.find("actual image 4x4 holds 63 bytes"), std::string::npos) << message;
}

TEST(GoldenCompare, SizeMismatchIsItsOwnOutcome) {
  const CompareResult result =
      compare_images(image::make_image(64, 48, kBackground), image::make_image(48, 64, kBackground));
  EXPECT_EQ(result.outcome, CompareOutcome::SizeMismatch);
  EXPECT_FALSE(result.passed());
  EXPECT_NE(result.message().find("golden is 64x48, actual is 48x64"), std::string::npos);
}

TEST(GoldenCompare, AlphaOnlyDifferenceIsDetectedAndNamed) {
  const image::Image golden = image::make_image(16, 16, kBackground);
  image::Image actual = golden;
  actual.set_pixel(3, 3, image::Rgba{30, 60, 90, 200});
  const CompareResult result = compare_images(golden, actual);
  EXPECT_EQ(result.outcome, CompareOutcome::ExceedsTolerance);
  EXPECT_TRUE(result.metrics.alpha_only);
  EXPECT_EQ(result.metrics.channel_max_delta[0], 0);
  EXPECT_EQ(result.metrics.channel_max_delta[3], 55);
  EXPECT_NE(result.message().find("only alpha differs"), std::string::npos);

  actual.set_pixel(4, 4, image::Rgba{31, 60, 90, 255});
  EXPECT_FALSE(compare_images(golden, actual).metrics.alpha_only);
}

// ---- tolerance -----------------------------------------------------------------------------

TEST(GoldenTolerance, DefaultIsStrictAndOverridesAreValidated) {
  EXPECT_TRUE(Tolerance{}.is_strict());
  EXPECT_EQ(Tolerance{}.describe_origin(), "strict default");
  const Tolerance partial = tolerance_from_json(json{{"max_channel_delta", 2}}, "sidecar 'x'");
  EXPECT_EQ(partial.max_channel_delta, 2);
  EXPECT_EQ(partial.max_differing_pixels, 0);
  EXPECT_EQ(partial.describe_origin(), "override from sidecar 'x'");

  std::string message =
      error_of([] { tolerance_from_json(json{{"max_pixels", 3}}, "sidecar 'x'"); });
  EXPECT_NE(message.find("sidecar 'x'"), std::string::npos) << message;
  EXPECT_NE(message.find("'max_pixels': unknown field"), std::string::npos) << message;
  message = error_of([] { tolerance_from_json(json{{"max_differing_ratio", 2.0}}, "o"); });
  EXPECT_NE(message.find("max_differing_ratio"), std::string::npos) << message;
  message = error_of([] { tolerance_from_json(json{{"max_channel_delta", 256}}, "o"); });
  EXPECT_NE(message.find("outside 0..255"), std::string::npos) << message;
  message = error_of([] { tolerance_from_json(json{{"window_size", "8"}}, "o"); });
  EXPECT_NE(message.find("expected an integer"), std::string::npos) << message;
  message = error_of([] { tolerance_from_json(json{{"max_differing_pixels", 10}}, "o"); });
  EXPECT_NE(message.find("must be loosened together"), std::string::npos) << message;
}

// ---- failure classes -----------------------------------------------------------------------

/// A check whose golden exists and whose state hash matches, comparing `golden` and `actual`.
GoldenCheck check_of(const image::Image& golden, const image::Image& actual) {
  GoldenCheck check;
  check.name = "circles/start";
  check.comparison = compare_images(golden, actual);
  check.expected_state_hash = 0x1111;
  check.actual_state_hash = 0x1111;
  check.expected_renderer = {"llvmpipe", "4.5 Mesa 22.3.6"};
  check.actual_renderer = check.expected_renderer;
  return check;
}

TEST(GoldenFailure, EachClassIsRecognisedWithItsOwnMessage) {
  const image::Image golden = image::make_image(16, 16, kBackground);
  image::Image changed = golden;
  shift_red(changed, 2, 2, 2, 20);

  GoldenCheck passing = check_of(golden, golden);
  EXPECT_EQ(classify_failure(passing), FailureClass::None);

  GoldenCheck missing = check_of(golden, golden);
  missing.golden_present = false;
  missing.comparison.reset();
  missing.expected_state_hash.reset();
  EXPECT_EQ(classify_failure(missing), FailureClass::MissingGolden);
  EXPECT_NE(failure_message(missing).find("golden 'circles/start': missing golden: "),
            std::string::npos);
  EXPECT_NE(failure_message(missing).find("promote_goldens.sh"), std::string::npos);

  GoldenCheck resized = check_of(golden, image::make_image(8, 16, kBackground));
  EXPECT_EQ(classify_failure(resized), FailureClass::SizeMismatch);
  EXPECT_NE(failure_message(resized).find("golden is 16x16, actual is 8x16"), std::string::npos);

  GoldenCheck diverged = check_of(golden, golden);  // same pixels: physics still decides
  diverged.actual_state_hash = 0x2222;
  diverged.moved_bodies = largest_drifts({{"ball 3", 1.0, 2.0, 0.0}, {"ground", 0.0, 0.0, 0.0}},
                                         {{"ball 3", 1.0, 2.5, 0.1}, {"ground", 0.0, 0.0, 0.0}},
                                         5);
  EXPECT_EQ(classify_failure(diverged), FailureClass::SimulationDiverged);
  const std::string diverged_message = failure_message(diverged);
  EXPECT_NE(diverged_message.find("simulation diverged"), std::string::npos);
  EXPECT_NE(diverged_message.find("0000000000002222"), std::string::npos);
  EXPECT_NE(diverged_message.find("0000000000001111"), std::string::npos);
  EXPECT_NE(diverged_message.find("ball 3 moved 0.5 m"), std::string::npos) << diverged_message;
  EXPECT_EQ(diverged_message.find("ground"), std::string::npos) << diverged_message;

  GoldenCheck rasterised = check_of(golden, changed);
  EXPECT_EQ(classify_failure(rasterised), FailureClass::RasterisationDiffers);
  EXPECT_NE(failure_message(rasterised).find("physics state matches"), std::string::npos);
  EXPECT_EQ(failure_message(rasterised).find("Renderer differs"), std::string::npos);
  rasterised.actual_renderer.gl_version = "4.5 Mesa 23.0.0";
  EXPECT_NE(failure_message(rasterised).find("Renderer differs"), std::string::npos);

  GoldenCheck flaky = check_of(golden, golden);
  flaky.second_render_identical = false;
  EXPECT_EQ(classify_failure(flaky), FailureClass::Nondeterminism);
  EXPECT_NE(failure_message(flaky).find("tolerance never absorbs this"), std::string::npos);
  flaky.golden_present = false;  // nondeterminism outranks everything else
  EXPECT_EQ(classify_failure(flaky), FailureClass::Nondeterminism);
}

TEST(GoldenFailure, NondeterminismIsNotAbsorbedByTolerance) {
  const image::Image golden = image::make_image(16, 16, kBackground);
  image::Image nearly = golden;
  shift_red(nearly, 1, 1, 1, 1);
  Tolerance generous;
  generous.max_channel_delta = 10;
  GoldenCheck check = check_of(golden, nearly);
  check.comparison = compare_images(golden, nearly, generous);
  ASSERT_TRUE(check.comparison->passed());
  check.second_render_identical = false;
  EXPECT_EQ(classify_failure(check), FailureClass::Nondeterminism);
}

TEST(GoldenBodyDrift, RanksUnmatchedFirstThenByDistance) {
  const std::vector<BodyPose> golden = {
      {"a", 0, 0, 0}, {"b", 0, 0, 0}, {"c", 0, 0, 0}, {"gone", 0, 0, 0}};
  const std::vector<BodyPose> actual = {
      {"a", 0.1, 0, 0}, {"b", 0, 3, 0}, {"c", 0, 0, 0.5}, {"new", 0, 0, 0}};
  const std::vector<BodyDrift> drifts = largest_drifts(golden, actual, 10);
  ASSERT_EQ(drifts.size(), 5u);
  EXPECT_EQ(drifts[0].name, "gone");
  EXPECT_EQ(drifts[0].note, "only in golden");
  EXPECT_EQ(drifts[1].name, "new");
  EXPECT_EQ(drifts[2].name, "b");
  EXPECT_DOUBLE_EQ(drifts[2].distance, 3.0);
  EXPECT_EQ(drifts[3].name, "a");
  EXPECT_EQ(drifts[4].name, "c");
  EXPECT_EQ(largest_drifts(golden, actual, 2).size(), 2u);
  EXPECT_EQ(describe_drifts({}), "no body moved");
}

// ---- sidecar -------------------------------------------------------------------------------

TEST(GoldenSidecar, RoundTripsThroughAFile) {
  TempDir dir;
  Sidecar sidecar = example_sidecar();
  sidecar.tolerance.max_channel_delta = 2;
  sidecar.tolerance.max_differing_pixels = 40;
  sidecar.tolerance.max_differing_ratio = 0.002;
  sidecar.tolerance.max_window_pixels = 3;
  const fs::path file = dir.path() / "circles" / "start.json";
  EXPECT_EQ(sidecar_path_for(dir.path() / "circles" / "start.png"), file);
  write_sidecar(file, sidecar);
  const Sidecar loaded = read_sidecar(file, "circles/start.json");
  EXPECT_EQ(loaded.scene, "circles");
  EXPECT_EQ(loaded.frame, 120);
  EXPECT_EQ(loaded.width, 64);
  EXPECT_EQ(loaded.height, 48);
  EXPECT_EQ(loaded.state_hash, 0x0123456789abcdefull);
  EXPECT_EQ(loaded.renderer, sidecar.renderer);
  EXPECT_EQ(loaded.tolerance.max_channel_delta, 2);
  EXPECT_EQ(loaded.tolerance.max_window_pixels, 3);
  EXPECT_EQ(loaded.tolerance.describe_origin(), "override from sidecar 'circles/start.json'");
  ASSERT_EQ(loaded.bodies.size(), 2u);
  EXPECT_EQ(loaded.bodies[1].name, "ball 1");
  EXPECT_EQ(loaded.bodies[1].angle, 0.125);
  EXPECT_NE(image::read_text_file(file).find("\"state_hash\": \"0123456789abcdef\""), std::string::npos);

  Sidecar unreadable = sidecar;
  unreadable.scene.clear();
  const std::string message = error_of([&] { write_sidecar(file, unreadable); });
  EXPECT_NE(message.find("field 'scene'"), std::string::npos) << message;
  EXPECT_EQ(read_sidecar(file).scene, "circles");  // the old file is untouched
}

TEST(GoldenSidecar, MissingToleranceMeansStrict) {
  json object = sidecar_to_json(example_sidecar());
  object.erase("tolerance");
  object.erase("bodies");
  const Sidecar sidecar = sidecar_from_json(object, "sidecar 'a.json'");
  EXPECT_TRUE(sidecar.tolerance.is_strict());
  EXPECT_TRUE(sidecar.bodies.empty());
}

TEST(GoldenSidecar, BadSidecarsNameTheFileAndField) {
  const json good = sidecar_to_json(example_sidecar());
  struct Case {
    std::function<void(json&)> corrupt;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](json& j) { j.erase("state_hash"); }, "field 'state_hash': missing"},
      {[](json& j) { j["state_hash"] = "xyz"; }, "field 'state_hash': expected 16 hex digits"},
      {[](json& j) { j["width"] = 0; }, "field 'width'"},
      {[](json& j) { j["frame"] = "ten"; }, "field 'frame': expected an integer"},
      {[](json& j) { j["scene"] = ""; }, "field 'scene': must not be empty"},
      {[](json& j) { j["format"] = 2; }, "field 'format': version 2 is not supported"},
      {[](json& j) { j["colour"] = "red"; }, "field 'colour': unknown field"},
      {[](json& j) { j["renderer"].erase("gl_version"); }, "field 'renderer.gl_version': missing"},
      {[](json& j) { j["renderer"] = 3; }, "field 'renderer': expected a JSON object"},
      {[](json& j) { j["bodies"][1]["x"] = "far"; }, "field 'bodies[1].x': expected a number"},
      {[](json& j) { j["tolerance"]["max_window_pixels"] = -1; },
       "tolerance field 'max_window_pixels'"},
  };
  for (const Case& test_case : cases) {
    json corrupted = good;
    test_case.corrupt(corrupted);
    const std::string message =
        error_of([&] { sidecar_from_json(corrupted, "sidecar 'circles/start.json'"); });
    EXPECT_NE(message.find("sidecar 'circles/start.json'"), std::string::npos) << message;
    EXPECT_NE(message.find(test_case.expected), std::string::npos)
        << "expected '" << test_case.expected << "' in: " << message;
  }
}

TEST(GoldenSidecar, UnreadableFilesAreClearErrors) {
  TempDir dir;
  std::string message = error_of([&] { read_sidecar(dir.path() / "none.json"); });
  EXPECT_NE(message.find("none.json"), std::string::npos) << message;
  const fs::path broken = dir.path() / "broken.json";
  image::write_text_file_atomically(broken, "{\"scene\": ");
  message = error_of([&] { read_sidecar(broken, "circles/broken.json"); });
  EXPECT_NE(message.find("sidecar 'circles/broken.json': not valid JSON"), std::string::npos)
      << message;
}

// ---- update modes --------------------------------------------------------------------------

TEST(GoldenUpdateMode, ParsesEveryModeAndRejectsOthers) {
  EXPECT_EQ(resolve_update_mode(nullptr, nullptr).mode, UpdateMode::None);
  EXPECT_EQ(resolve_update_mode("", nullptr).mode, UpdateMode::None);
  EXPECT_EQ(resolve_update_mode("none", nullptr).mode, UpdateMode::None);
  EXPECT_EQ(resolve_update_mode("missing", nullptr).mode, UpdateMode::Missing);
  EXPECT_EQ(resolve_update_mode("changed", "false").mode, UpdateMode::Changed);
  EXPECT_EQ(resolve_update_mode("all", "").mode, UpdateMode::All);
  EXPECT_TRUE(resolve_update_mode("all", nullptr).note.empty());
  const std::string message = error_of([] { resolve_update_mode("everything", nullptr); });
  EXPECT_NE(message.find("GOLDEN_UPDATE='everything'"), std::string::npos) << message;
  EXPECT_NE(message.find("none, missing, changed, all"), std::string::npos) << message;
  EXPECT_THROW(resolve_update_mode("ALL", "true"), GoldenError);  // invalid even under CI
}

TEST(GoldenUpdateMode, CiForcesNoneAndSaysWhy) {
  for (const char* ci : {"true", "TRUE", "1", "yes", "Yes", "on"}) {
    const UpdateModeChoice choice = resolve_update_mode("all", ci);
    EXPECT_EQ(choice.mode, UpdateMode::None) << ci;
    EXPECT_NE(choice.note.find("GOLDEN_UPDATE=all ignored"), std::string::npos) << choice.note;
    EXPECT_NE(choice.note.find("forces none"), std::string::npos) << choice.note;
  }
  EXPECT_TRUE(resolve_update_mode("none", "true").note.empty());
  for (const char* not_ci : {"false", "FALSE", "0", "no", "off", ""}) {
    EXPECT_EQ(resolve_update_mode("all", not_ci).mode, UpdateMode::All) << not_ci;
  }
}

TEST(GoldenUpdateMode, ReadsTheEnvironment) {
  testing::ScopedEnvironment environment;
  environment.set("GOLDEN_UPDATE", "missing");
  environment.set("CI", "false");
  EXPECT_EQ(update_mode_from_environment().mode, UpdateMode::Missing);
  environment.set("CI", "true");
  EXPECT_EQ(update_mode_from_environment().mode, UpdateMode::None);
  environment.set("GOLDEN_UPDATE", nullptr);
  environment.set("CI", nullptr);
  EXPECT_EQ(update_mode_from_environment().mode, UpdateMode::None);

  environment.set("GOLDEN_ARTIFACT_DIR", "/tmp/chosen");
  EXPECT_EQ(artifact_root_from_environment("build/golden"), fs::path("/tmp/chosen"));
  environment.set("GOLDEN_ARTIFACT_DIR", nullptr);
  EXPECT_EQ(artifact_root_from_environment("build/golden"), fs::path("build/golden"));
}

TEST(GoldenUpdateMode, DecidesWhichGoldensToWrite) {
  using F = FailureClass;
  EXPECT_FALSE(should_write_golden(UpdateMode::None, F::MissingGolden));
  EXPECT_TRUE(should_write_golden(UpdateMode::Missing, F::MissingGolden));
  EXPECT_FALSE(should_write_golden(UpdateMode::Missing, F::RasterisationDiffers));
  EXPECT_TRUE(should_write_golden(UpdateMode::Changed, F::SimulationDiverged));
  EXPECT_TRUE(should_write_golden(UpdateMode::Changed, F::SizeMismatch));
  EXPECT_FALSE(should_write_golden(UpdateMode::Changed, F::None));
  EXPECT_TRUE(should_write_golden(UpdateMode::All, F::None));
  for (UpdateMode mode :
       {UpdateMode::None, UpdateMode::Missing, UpdateMode::Changed, UpdateMode::All}) {
    EXPECT_FALSE(should_write_golden(mode, F::Nondeterminism)) << update_mode_name(mode);
  }
}

// ---- pictures, artifacts and the report ------------------------------------------------------

TEST(GoldenDiffImages, OverlayMarksDifferencesAndHeatmapScalesToTheLargest) {
  const image::Image golden = image::make_image(8, 8, kBackground);
  image::Image actual = golden;
  shift_red(actual, 1, 1, 1, 40);
  shift_red(actual, 2, 2, 1, 2);
  const image::Image overlay = diff_overlay(golden, actual, 2);
  EXPECT_EQ(overlay.pixel(1, 1).r, 255);
  EXPECT_EQ(overlay.pixel(1, 1).g, 0);
  EXPECT_EQ(overlay.pixel(2, 2).g, 200);  // changed within tolerance: yellow
  const image::Rgba grey = overlay.pixel(5, 5);
  EXPECT_EQ(grey.r, grey.g);
  EXPECT_EQ(grey.g, grey.b);
  EXPECT_GT(grey.r, 180);

  const image::Image heatmap = diff_heatmap(golden, actual);
  const image::Rgba hottest = heatmap.pixel(1, 1);
  EXPECT_EQ(hottest.r, 255);
  EXPECT_EQ(hottest.g, 255);
  EXPECT_EQ(hottest.b, 255);
  EXPECT_GT(heatmap.pixel(2, 2).r, 0);
  EXPECT_EQ(heatmap.pixel(5, 5).r, 0);
}

TEST(GoldenArtifacts, WritesEveryFileAndOneSelfContainedReport) {
  TempDir dir;
  const image::Image golden = image::make_image(24, 16, kBackground);
  image::Image actual = golden;
  shift_red(actual, 4, 4, 5, 30);

  GoldenCheck rasterised = check_of(golden, actual);
  Sidecar sidecar = example_sidecar();
  const fs::path first = write_failure_artifacts(dir.path(), rasterised, actual, &golden, &sidecar);
  EXPECT_EQ(first, dir.path() / "circles" / "start");
  for (const char* file :
       {"actual.png", "actual.json", "expected.png", "diff.png", "heatmap.png", "metrics.json"}) {
    EXPECT_TRUE(fs::is_regular_file(first / file)) << file;
  }
  const json metrics = json::parse(image::read_text_file(first / "metrics.json"));
  EXPECT_EQ(metrics["class"], "rasterisation_differs");
  EXPECT_EQ(metrics["comparison"]["metrics"]["differing_pixels"], 25);
  EXPECT_EQ(metrics["comparison"]["tolerance"]["origin"], "strict default");
  EXPECT_EQ(image::load_png(first / "actual.png").hash(), actual.hash());

  GoldenCheck missing;
  missing.name = "stack/settled";
  missing.golden_present = false;
  const fs::path second = write_failure_artifacts(dir.path(), missing, actual, nullptr, &sidecar);
  EXPECT_TRUE(fs::is_regular_file(second / "actual.png"));
  EXPECT_FALSE(fs::exists(second / "expected.png"));

  EXPECT_EQ(write_html_report(dir.path()), 2);
  const std::string html = image::read_text_file(dir.path() / "index.html");
  EXPECT_NE(html.find("circles/start"), std::string::npos);
  EXPECT_NE(html.find("stack/settled"), std::string::npos);
  EXPECT_NE(html.find("rasterisation differs"), std::string::npos);
  EXPECT_NE(html.find("missing golden"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  EXPECT_EQ(html.find("src=\"actual.png\""), std::string::npos);  // nothing links outside

  // Rewriting a failure drops files the new failure does not produce.
  write_failure_artifacts(dir.path(), missing, actual, nullptr, nullptr);
  EXPECT_FALSE(fs::exists(second / "actual.json"));
}

TEST(GoldenArtifacts, RefusesNamesThatEscapeTheRoot) {
  TempDir dir;
  GoldenCheck check;
  const image::Image image = image::make_image(2, 2, kBackground);
  for (const char* name : {"", "../outside", "/abs/path", "a/./b"}) {
    check.name = name;
    EXPECT_THROW(write_failure_artifacts(dir.path(), check, image, nullptr, nullptr),
                 GoldenError)
        << name;
  }
}

TEST(GoldenReport, ListsAnUnreadableMetricsFileInsteadOfStopping) {
  TempDir dir;
  image::write_text_file_atomically(dir.path() / "circles" / "broken" / "metrics.json", "[1, 2");
  image::write_text_file_atomically(dir.path() / "circles" / "array" / "metrics.json", "[1, 2]");
  EXPECT_EQ(write_html_report(dir.path()), 2);
  const std::string html = image::read_text_file(dir.path() / "index.html");
  EXPECT_NE(html.find("circles/broken"), std::string::npos);
  EXPECT_NE(html.find("unreadable: 2"), std::string::npos);
  EXPECT_EQ(write_html_report(dir.path() / "absent"), 0);
}

TEST(GoldenReport, EscapesHtml) {
  EXPECT_EQ(escape_html("<a href=\"x\">&'"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

// ---- inventory -----------------------------------------------------------------------------

TEST(GoldenInventory, FindsGoldensUnusedOnesAndUnpairedFiles) {
  TempDir dir;
  const image::Image image = image::make_image(2, 2, kBackground);
  image::save_png(dir.path() / "circles" / "start.png", image);
  write_sidecar(dir.path() / "circles" / "start.json", example_sidecar());
  image::save_png(dir.path() / "circles" / "mid.png", image);
  write_sidecar(dir.path() / "stack" / "settled.json", example_sidecar());
  image::save_png(dir.path() / "stack" / "top.png", image);
  write_sidecar(dir.path() / "stack" / "top.json", example_sidecar());
  image::write_text_file_atomically(dir.path() / "README.md", "goldens");

  const GoldenInventory inventory = scan_goldens(dir.path());
  EXPECT_EQ(inventory.goldens, (std::vector<std::string>{"circles/start", "stack/top"}));
  EXPECT_EQ(inventory.missing_sidecar, std::vector<std::string>{"circles/mid"});
  EXPECT_EQ(inventory.missing_image, std::vector<std::string>{"stack/settled"});
  EXPECT_EQ(unused_goldens(inventory.goldens, {"circles/start", "other/thing"}),
            std::vector<std::string>{"stack/top"});
  EXPECT_TRUE(scan_goldens(dir.path() / "absent").goldens.empty());
}

// ---- promote script --------------------------------------------------------------------------

/// Runs the promote script with GOLDEN_IMAGES_DIR set; returns its exit status.
int run_promote(const fs::path& golden_dir, const std::string& arguments) {
  const char* source = std::getenv("IMPULSE2D_SOURCE_DIR");
  const std::string command = "GOLDEN_IMAGES_DIR='" + golden_dir.string() + "' '" +
                              std::string(source) + "/scripts/promote_goldens.sh' " + arguments +
                              " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GoldenPromote, CopiesReviewedActualsAndRefusesWhenNothingToPromote) {
  if (std::getenv("IMPULSE2D_SOURCE_DIR") == nullptr) GTEST_SKIP() << "run through ctest";
  TempDir dir;
  const fs::path artifacts = dir.path() / "artifacts";
  const fs::path goldens = dir.path() / "golden_images";
  const image::Image actual = image::make_image(6, 4, kBackground);
  const Sidecar sidecar = example_sidecar();

  fs::create_directories(artifacts);
  EXPECT_NE(run_promote(goldens, "'" + artifacts.string() + "'"), 0);  // empty: refuse

  GoldenCheck missing;
  missing.name = "circles/start";
  missing.golden_present = false;
  write_failure_artifacts(artifacts, missing, actual, nullptr, &sidecar);
  GoldenCheck no_sidecar = missing;
  no_sidecar.name = "circles/mid";
  write_failure_artifacts(artifacts, no_sidecar, actual, nullptr, nullptr);
  GoldenCheck flaky = missing;
  flaky.name = "stack/settled";
  flaky.second_render_identical = false;
  write_failure_artifacts(artifacts, flaky, actual, nullptr, &sidecar);

  EXPECT_EQ(run_promote(goldens, "--dry-run '" + artifacts.string() + "'"), 0);
  EXPECT_FALSE(fs::exists(goldens));
  EXPECT_NE(run_promote(goldens, "'" + artifacts.string() + "' circles/mid"), 0);
  EXPECT_NE(run_promote(goldens, "'" + artifacts.string() + "' stack/settled"), 0);
  EXPECT_FALSE(fs::exists(goldens));

  EXPECT_EQ(run_promote(goldens, "'" + artifacts.string() + "'"), 0);
  EXPECT_EQ(image::load_png(goldens / "circles" / "start.png").hash(), actual.hash());
  EXPECT_EQ(read_sidecar(goldens / "circles" / "start.json").state_hash, sidecar.state_hash);
  EXPECT_FALSE(fs::exists(goldens / "circles" / "mid.png"));
  EXPECT_FALSE(fs::exists(goldens / "stack" / "settled.png"));
}

}  // namespace
}  // namespace impulse2d::golden

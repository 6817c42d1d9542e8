/// @file screenshot_golden.cpp
#include "tests/app/screenshot_golden.h"

#include <nlohmann/json.hpp>

#include "golden/compare.h"
#include "golden/diff_images.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "image/image.h"
#include "image/png.h"
#include "golden/update_mode.h"

namespace impulse2d::testing {
namespace fs = std::filesystem;
using namespace impulse2d::golden;

ScreenshotCheck check_screenshot(const std::string& name, const fs::path& screenshot,
                                 const CheckSettings& settings) {
  const fs::path golden = golden_png_path(settings.golden_dir, name);
  const fs::path sidecar_file = fs::path(golden).replace_extension(".json");
  const nlohmann::json sidecar =
      nlohmann::json::parse(image::read_text_file(sidecar_file), nullptr, false);
  if (!sidecar.is_object() || !sidecar.contains("tolerance") ||
      !sidecar.value("tolerance_reason", nlohmann::json()).is_string() ||
      !sidecar.value("description", nlohmann::json()).is_string()) {
    throw GoldenError("'" + sidecar_file.string() +
                      "' must be a JSON object with description, tolerance and tolerance_reason");
  }
  const Tolerance tolerance =
      tolerance_from_json(sidecar["tolerance"], "sidecar '" + name + ".json'");
  const image::Image actual = image::load_png(screenshot);

  ScreenshotCheck check;
  FailureClass outcome = FailureClass::MissingGolden;
  if (fs::exists(golden)) {
    const image::Image expected = image::load_png(golden);
    const CompareResult compared = compare_images(expected, actual, tolerance);
    outcome = compared.passed() ? FailureClass::None
              : compared.outcome == CompareOutcome::SizeMismatch
                  ? FailureClass::SizeMismatch
                  : FailureClass::RasterisationDiffers;
    check.message = name + " (" + sidecar["description"].get<std::string>() + "): " +
                    compared.message();
    if (!compared.passed() && !settings.artifact_root.empty()) {
      const fs::path artifacts = settings.artifact_root / name;
      image::save_png(artifacts / "actual.png", actual);
      image::save_png(artifacts / "expected.png", expected);
      if (compared.outcome != CompareOutcome::SizeMismatch) {
        image::save_png(artifacts / "diff.png", diff_overlay(expected, actual, tolerance.max_channel_delta));
      }
      check.message += "\nactual, expected and diff: " + artifacts.string();
    }
  } else {
    check.message = "no golden " + golden.string() +
                    " (GOLDEN_UPDATE=missing writes it from this run)";
  }
  check.message += "\ntolerance: " + sidecar["tolerance_reason"].get<std::string>();
  if (should_write_golden(settings.update_mode, outcome)) {
    image::save_png(golden, actual);
    check.golden_written = true;
    check.message += "\nwritten as the golden (GOLDEN_UPDATE=" +
                     update_mode_name(settings.update_mode) + ")";
  }
  check.passed = outcome == FailureClass::None || check.golden_written;
  return check;
}

}  // namespace impulse2d::testing

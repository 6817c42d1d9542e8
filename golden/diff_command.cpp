/// @file diff_command.cpp
#include "golden/diff_command.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "golden/compare.h"
#include "golden/compare_json.h"
#include "golden/diff_images.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "image/image.h"
#include "image/png.h"
#include "golden/report.h"

namespace impulse2d::golden {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// What the two frames' PNG metadata says about why they differ; empty when either lacks
/// a state hash (a PNG not written by the golden tools).
std::string metadata_verdict(const image::Image& expected, const image::Image& actual) {
  const auto value = [](const image::Image& image, const char* key) {
    const auto found = image.text.find(key);
    return found == image.text.end() ? std::string() : found->second;
  };
  const std::string hash_a = value(expected, image::png_keys::kStateHash);
  const std::string hash_b = value(actual, image::png_keys::kStateHash);
  if (hash_a.empty() || hash_b.empty()) return "";
  const auto describe = [&](const image::Image& image) {
    return value(image, image::png_keys::kScene) + " step " + value(image, image::png_keys::kStep) + " (" +
           value(image, image::png_keys::kTime) + " s), state " + value(image, image::png_keys::kStateHash) +
           ", " + value(image, image::png_keys::kRenderer) + ", " + value(image, image::png_keys::kSoftware);
  };
  std::string verdict = "metadata: a is " + describe(expected) + "; b is " + describe(actual) +
                        ". ";
  if (value(expected, image::png_keys::kScene) != value(actual, image::png_keys::kScene) ||
      value(expected, image::png_keys::kStep) != value(actual, image::png_keys::kStep) ||
      value(expected, image::png_keys::kParameters) != value(actual, image::png_keys::kParameters)) {
    return verdict + "They are frames of different scenes, steps or parameters";
  }
  if (hash_a != hash_b) return verdict + "Physics state differs: simulation diverged";
  if (value(expected, image::png_keys::kRenderer) != value(actual, image::png_keys::kRenderer)) {
    return verdict + "Same physics state, different renderers: any pixel difference is theirs";
  }
  return verdict + "Same physics state and renderer: any pixel difference is rasterisation";
}

/// Writes the images, metrics.json and index.html of a mismatch into `directory`; returns
/// the report's path.
fs::path write_diff_artifacts(const fs::path& directory, const std::string& title,
                              const CompareResult& result, const image::Image& expected,
                              const image::Image& actual) {
  json files = json::object();
  auto write_artifact = [&](const std::string& key, const image::Image& image) {
    image::save_png(directory / (key + ".png"), image);
    files[key] = key + ".png";
  };
  write_artifact("expected", expected);
  write_artifact("actual", actual);
  if (result.outcome != CompareOutcome::SizeMismatch) {
    write_artifact("diff", diff_overlay(expected, actual, result.tolerance.max_channel_delta));
    write_artifact("heatmap", diff_heatmap(expected, actual));
  }
  const bool size_mismatch = result.outcome == CompareOutcome::SizeMismatch;
  const std::string class_name = result.passed() ? "within tolerance"
                                 : size_mismatch ? "size mismatch"
                                                 : "images differ";
  std::string class_id = class_name;
  std::replace(class_id.begin(), class_id.end(), ' ', '_');
  const json metrics = {{"name", title},
                        {"class", class_id},
                        {"class_name", class_name},
                        {"message", result.message()},
                        {"metadata", metadata_verdict(expected, actual)},
                        {"comparison", comparison_to_json(result)},
                        {"files", files}};
  image::write_text_file_atomically(directory / "metrics.json", metrics.dump(2) + "\n");
  write_html_report(directory);
  return directory / "index.html";
}

/// `write_diff_artifacts`, all or nothing: on failure (a full disk) the artifacts that did
/// not exist before and the directory if it was created are removed before rethrowing.
fs::path write_artifacts_or_nothing(const fs::path& directory, const std::string& title,
                                    const CompareResult& result, const image::Image& expected,
                                    const image::Image& actual) {
  std::error_code error;
  const bool directory_existed = fs::exists(directory, error);
  std::vector<fs::path> new_files;
  for (const char* name : {"expected.png", "actual.png", "diff.png", "heatmap.png",
                           "metrics.json", "index.html"}) {
    if (!fs::exists(directory / name, error)) new_files.push_back(directory / name);
  }
  try {
    return write_diff_artifacts(directory, title, result, expected, actual);
  } catch (...) {
    for (const fs::path& file : new_files) fs::remove(file, error);
    if (!directory_existed) fs::remove(directory, error);
    throw;
  }
}

}  // namespace

int run_diff_command(const std::string& expected_png, const std::string& actual_png,
                     const std::string& out_dir, std::ostream& out, std::ostream& err,
                     const DiffLimits& limits) {
  try {
    const Tolerance tolerance = tolerance_from_limits(limits, "command-line limits");
    const image::Image expected = image::load_png(expected_png);
    const image::Image actual = image::load_png(actual_png);
    const CompareResult result = compare_images(expected, actual, tolerance);
    out << expected_png << " vs " << actual_png << ": " << result.message() << "\n";
    const std::string metadata = metadata_verdict(expected, actual);
    if (!metadata.empty()) out << metadata << "\n";
    if (result.outcome != CompareOutcome::ExactMatch && !out_dir.empty()) {
      const fs::path report = write_artifacts_or_nothing(
          out_dir, expected_png + " vs " + actual_png, result, expected, actual);
      out << "report: " << report.string() << "\n";
    }
    return result.passed() ? kDiffSame : kDiffDiffers;
  } catch (const GoldenError& error) {
    err << "impulse2d: diff: " << error.what() << "\n";
    return kDiffError;
  }
}

}  // namespace impulse2d::golden

/// @file artifacts.cpp
#include "image/png.h"
#include "golden/artifacts.h"

#include "golden/compare_json.h"
#include "golden/json_output.h"
#include "golden/diff_images.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "image/hex_hash.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

namespace impulse2d::golden {

namespace {

using nlohmann::json;

json check_to_json(const GoldenCheck& check, const json& files) {
  const FailureClass failure_class = classify_failure(check);
  json drifts = json::array();
  for (const BodyDrift& drift : check.moved_bodies) {
    drifts.push_back({{"name", drift.name},
                      {"distance", drift.distance},
                      {"rotation", drift.rotation},
                      {"note", drift.note}});
  }
  json noise = nullptr;
  if (check.noise) {
    json escapes = json::array();
    for (const EnvelopeEscape& escape : check.noise->escapes) {
      escapes.push_back({{"what", escape.what},
                         {"measured", escape.measured},
                         {"envelope", escape.envelope},
                         {"unit", escape.unit}});
    }
    noise = {{"within", check.noise->within()},
             {"cannot_tell", check.noise->cannot_tell()},
             {"compared", check.noise->compared},
             {"scene_scale", check.noise->scene_scale},
             {"bound", check.noise->bound},
             {"largest_move", check.noise->largest_move},
             {"envelope_reach", check.noise->envelope_reach},
             {"stops_telling_step", check.noise->stops_telling_step},
             {"last_telling_step", check.noise->last_telling_step},
             {"unsampled_living_set", check.noise->unsampled_living_set},
             {"escapes", std::move(escapes)}};
  }
  return {{"name", check.name},
          {"class", failure_class_id(failure_class)},
          {"class_name", failure_class_name(failure_class)},
          {"message", failure_message(check)},
          {"expected_state_hash", check.expected_state_hash
                                      ? json(image::to_hex_hash(*check.expected_state_hash))
                                      : json(nullptr)},
          {"actual_state_hash", image::to_hex_hash(check.actual_state_hash)},
          {"second_render_identical", check.second_render_identical},
          {"other_process_identical", check.other_process_identical},
          {"expected_renderer", check.expected_renderer.describe()},
          {"actual_renderer", check.actual_renderer.describe()},
          {"moved_bodies", drifts},
          {"noise", noise},
          {"comparison", check.comparison ? comparison_to_json(*check.comparison) : json(nullptr)},
          {"files", files}};
}

/// <root>/<name>, refusing names that would escape the root.
std::filesystem::path failure_directory(const std::filesystem::path& root,
                                        const std::string& name) {
  const std::filesystem::path relative(name);
  bool valid = !name.empty() && relative.is_relative();
  for (const auto& part : relative) {
    if (part == ".." || part == ".") valid = false;
  }
  if (!valid) {
    throw GoldenError("golden name '" + name +
                      "' must be a relative path like 'scene/golden' without '.' or '..'");
  }
  return root / relative;
}

}  // namespace

std::filesystem::path artifact_root_from_environment(const std::filesystem::path& fallback) {
  const char* value = std::getenv("GOLDEN_ARTIFACT_DIR");
  if (value != nullptr && value[0] != '\0') return std::filesystem::path(value);
  return fallback;
}

std::filesystem::path write_failure_artifacts(const std::filesystem::path& root,
                                              const GoldenCheck& check, const image::Image& actual,
                                              const image::Image* expected,
                                              const Sidecar* actual_sidecar) {
  const std::filesystem::path directory = failure_directory(root, check.name);
  // A previous failure of the same golden may have left files this one would not write.
  for (const char* stale : {"actual.png", "actual.json", "expected.png", "diff.png",
                            "heatmap.png", "metrics.json"}) {
    std::error_code ignored;
    std::filesystem::remove(directory / stale, ignored);
  }
  json files = json::object();
  auto write_artifact = [&](const std::string& key, const image::Image& image) {
    image::save_png(directory / (key + ".png"), image);
    files[key] = key + ".png";
  };
  write_artifact("actual", actual);
  if (actual_sidecar != nullptr) {
    write_sidecar(directory / "actual.json", *actual_sidecar);
    files["actual_sidecar"] = "actual.json";
  }
  if (expected != nullptr) {
    write_artifact("expected", *expected);
    if (expected->width == actual.width && expected->height == actual.height) {
      const int max_channel_delta =
          check.comparison ? check.comparison->tolerance.max_channel_delta : 0;
      write_artifact("diff", diff_overlay(*expected, actual, max_channel_delta));
      write_artifact("heatmap", diff_heatmap(*expected, actual));
    }
  }
  const std::filesystem::path metrics = directory / "metrics.json";
  image::write_text_file_atomically(
      metrics, dump_json_for_file(check_to_json(check, files), metrics.string()));
  return directory;
}

}  // namespace impulse2d::golden

/// @file golden_block.cpp
#include "golden/scenes/golden_block.h"

#include <nlohmann/json.hpp>

#include <set>

#include "scene/overlays.h"
#include "scene/scene_loader.h"
#include "scene/usage_error.h"
#include "golden/diff_limits.h"
#include "golden/error.h"
#include "image/file_io.h"
#include "golden/json_fields.h"

namespace impulse2d::golden {

namespace {

using nlohmann::json;

bool valid_frame_name(const std::string& name) {
  return !name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRST"
                                                 "UVWXYZ0123456789_-") == std::string::npos;
}

Tolerance read_tolerance(const FieldReader& block, const std::string& file) {
  if (!block.has("tolerance")) return Tolerance{};
  const FieldReader tolerance(block.get("tolerance"), file, "golden.tolerance.");
  tolerance.reject_unknown({"threshold", "max_diff_pixels", "max_diff_ratio", "masks"});
  DiffLimits limits;
  if (tolerance.has("threshold")) {
    limits.threshold = tolerance.integer("threshold", 0);
    if (limits.threshold > 255) {
      tolerance.fail("threshold", tolerance.get("threshold").dump() + " is out of range (0..255)");
    }
  }
  if (tolerance.has("max_diff_pixels")) {
    limits.max_diff_pixels = tolerance.integer("max_diff_pixels", 0);
  }
  if (tolerance.has("max_diff_ratio")) {
    limits.max_diff_ratio = tolerance.number("max_diff_ratio");
    if (!(*limits.max_diff_ratio >= 0.0 && *limits.max_diff_ratio <= 1.0)) {
      tolerance.fail("max_diff_ratio",
                     tolerance.get("max_diff_ratio").dump() + " is out of range (0..1)");
    }
  }
  if (tolerance.has("masks")) {
    const json& masks = tolerance.array("masks");
    for (std::size_t i = 0; i < masks.size(); ++i) {
      const json& mask = masks[i];
      bool valid = mask.is_array() && mask.size() == 4;
      std::string text;
      for (std::size_t k = 0; valid && k < 4; ++k) {
        valid = mask[k].is_number_integer() && mask[k].get<std::int64_t>() >= (k < 2 ? 0 : 1) &&
                mask[k].get<std::int64_t>() <= 1'000'000'000;
        if (valid) text += (k == 0 ? "" : ",") + mask[k].dump();
      }
      if (!valid) {
        tolerance.fail("masks[" + std::to_string(i) + "]",
                       "expected [x, y, width, height] (integers; x, y >= 0; width, height >= "
                       "1), got " + mask.dump());
      }
      limits.masks.push_back(text);
    }
  }
  try {
    return tolerance_from_limits(limits, "the golden block of " + file);
  } catch (const GoldenError& error) {
    throw GoldenError(file + ": field 'golden.tolerance': " + error.what());
  }
}

}  // namespace

SceneGoldens read_scene_goldens(const std::string& scene_file) {
  const demos::Scene scene = demos::load_scene_file(scene_file);
  json document;
  try {
    document = json::parse(image::read_text_file(scene_file));
  } catch (const json::parse_error& error) {
    throw GoldenError(scene_file + ": not valid JSON: " + error.what());
  }
  const FieldReader top(document, scene_file, "");
  if (!top.has("golden")) {
    top.fail("golden",
             "missing: add a \"golden\" block naming the frames to keep, e.g. "
             "{\"frames\": [{\"name\": \"start\", \"step\": 0}]}");
  }
  const FieldReader block(top.get("golden"), scene_file, "golden.");
  block.reject_unknown({"dir", "size", "tolerance", "frames"});

  SceneGoldens goldens;
  goldens.scene_file = scene_file;
  const std::filesystem::path base = std::filesystem::path(scene_file).parent_path();
  goldens.golden_dir = base / (block.has("dir") ? block.string("dir", false) : "goldens");
  int width = kGoldenWidth;
  int height = kGoldenHeight;
  if (block.has("size")) {
    const json& size = block.array("size");
    if (size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer() ||
        size[0].get<int>() < 16 || size[0].get<int>() > 2048 || size[1].get<int>() < 16 ||
        size[1].get<int>() > 2048) {
      block.fail("size", "expected [width, height], each 16..2048 pixels, got " + size.dump());
    }
    width = size[0].get<int>();
    height = size[1].get<int>();
  }
  goldens.tolerance = read_tolerance(block, scene_file);

  const json& frames = block.array("frames");
  if (frames.empty()) block.fail("frames", "must name at least one frame");
  std::set<std::string> names;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const FieldReader frame(frames[i], scene_file, "golden.frames[" + std::to_string(i) + "].");
    frame.reject_unknown({"name", "step", "overlays", "theme"});
    GoldenSpec spec;
    spec.scene = scene.name;
    spec.scene_file = scene_file;
    spec.width = width;
    spec.height = height;
    spec.name = frame.string("name", false);
    if (!valid_frame_name(spec.name)) {
      frame.fail("name", "\"" + spec.name + "\" must use only letters, digits, '_' and '-'");
    }
    if (!names.insert(spec.name).second) frame.fail("name", "\"" + spec.name + "\" repeats");
    spec.step = frame.integer("step", 0);
    if (spec.step > kMaxGoldenStep) {
      frame.fail("step", std::to_string(spec.step) + " is beyond " +
                             std::to_string(kMaxGoldenStep) +
                             " (each check simulates from step 0)");
    }
    if (frame.has("overlays")) {
      try {
        spec.overlays = demos::parse_overlays(frame.string("overlays", false));
      } catch (const demos::UsageError& error) {
        frame.fail("overlays", error.what());
      }
    }
    if (frame.has("theme")) {
      const std::string theme = frame.string("theme", false);
      if (theme != "light" && theme != "dark") {
        frame.fail("theme", "\"" + theme + "\": expected light or dark");
      }
      spec.dark_theme = theme == "dark";
    }
    goldens.frames.push_back(spec);
  }
  return goldens;
}

}  // namespace impulse2d::golden

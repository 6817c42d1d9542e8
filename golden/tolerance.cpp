/// @file tolerance.cpp
#include "golden/tolerance.h"

#include "golden/error.h"

#include <nlohmann/json.hpp>

#include <limits>

namespace impulse2d::golden {

namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& field,
                       const std::string& reason) {
  throw GoldenError(origin + ": tolerance field '" + field + "': " + reason);
}

std::int64_t read_count(const nlohmann::json& value, const std::string& origin,
                        const std::string& field, std::int64_t upper_limit) {
  if (!value.is_number_integer()) fail(origin, field, "expected an integer, got " + value.dump());
  const std::int64_t count = value.get<std::int64_t>();
  if (count < 0 || count > upper_limit) {
    fail(origin, field,
         std::to_string(count) + " is outside 0.." + std::to_string(upper_limit));
  }
  return count;
}

}  // namespace

bool Tolerance::is_strict() const {
  return max_channel_delta == 0 && max_differing_pixels == 0 && max_differing_ratio == 0.0 &&
         max_window_pixels == 0 && masks.empty();
}

std::string Tolerance::describe_origin() const {
  if (is_strict()) return "strict default";
  return origin.empty() ? "override" : "override from " + origin;
}

Tolerance tolerance_from_json(const nlohmann::json& object, const std::string& origin) {
  if (!object.is_object()) {
    throw GoldenError(origin + ": tolerance: expected a JSON object, got " + object.dump());
  }
  Tolerance tolerance;
  tolerance.origin = origin;
  constexpr std::int64_t kIntLimit = 1'000'000'000;
  for (const auto& [field, value] : object.items()) {
    if (field == "max_channel_delta") {
      tolerance.max_channel_delta = static_cast<int>(read_count(value, origin, field, 255));
    } else if (field == "max_differing_pixels") {
      tolerance.max_differing_pixels =
          read_count(value, origin, field, std::numeric_limits<std::int64_t>::max());
    } else if (field == "max_differing_ratio") {
      if (!value.is_number()) fail(origin, field, "expected a number, got " + value.dump());
      const double ratio = value.get<double>();
      if (!(ratio >= 0.0 && ratio <= 1.0)) fail(origin, field, value.dump() + " is outside 0..1");
      tolerance.max_differing_ratio = ratio;
    } else if (field == "window_size") {
      tolerance.window_size = static_cast<int>(read_count(value, origin, field, kIntLimit));
      if (tolerance.window_size == 0) fail(origin, field, "must be at least 1");
    } else if (field == "masks") {
      if (!value.is_array()) fail(origin, field, "expected an array of [x, y, width, height]");
      for (const auto& item : value) {
        if (!item.is_array() || item.size() != 4) {
          fail(origin, field, "each mask is [x, y, width, height], got " + item.dump());
        }
        MaskRect mask;
        mask.x = static_cast<int>(read_count(item[0], origin, field + ".x", kIntLimit));
        mask.y = static_cast<int>(read_count(item[1], origin, field + ".y", kIntLimit));
        mask.width = static_cast<int>(read_count(item[2], origin, field + ".width", kIntLimit));
        mask.height = static_cast<int>(read_count(item[3], origin, field + ".height", kIntLimit));
        if (mask.width < 1 || mask.height < 1) {
          fail(origin, field, "a mask's width and height must be at least 1, got " + item.dump());
        }
        tolerance.masks.push_back(mask);
      }
    } else if (field == "max_window_pixels") {
      tolerance.max_window_pixels = static_cast<int>(read_count(value, origin, field, kIntLimit));
    } else {
      fail(origin, field,
           "unknown field (known: max_channel_delta, max_differing_pixels, "
           "max_differing_ratio, window_size, max_window_pixels, masks)");
    }
  }
  // The three pixel-count layers must all hold, so loosening one while another stays 0
  // changes nothing: any differing pixel would still fail. Say so instead of ignoring it.
  const bool pixels_loose = tolerance.max_differing_pixels > 0;
  const bool ratio_loose = tolerance.max_differing_ratio > 0.0;
  const bool window_loose = tolerance.max_window_pixels > 0;
  if ((pixels_loose || ratio_loose || window_loose) &&
      !(pixels_loose && ratio_loose && window_loose)) {
    throw GoldenError(origin +
                      ": tolerance: max_differing_pixels, max_differing_ratio and "
                      "max_window_pixels must be loosened together (each must hold, so one "
                      "left at 0 still fails any differing pixel); got " +
                      std::to_string(tolerance.max_differing_pixels) + ", " +
                      nlohmann::json(tolerance.max_differing_ratio).dump() + ", " +
                      std::to_string(tolerance.max_window_pixels));
  }
  return tolerance;
}

MaskRect parse_mask(const std::string& text, const std::string& origin) {
  MaskRect mask;
  int* fields[] = {&mask.x, &mask.y, &mask.width, &mask.height};
  std::size_t start = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t end = i < 3 ? text.find(',', start) : text.size();
    const std::string part =
        end == std::string::npos ? std::string() : text.substr(start, end - start);
    const bool digits = !part.empty() && part.size() <= 9 &&
                        part.find_first_not_of("0123456789") == std::string::npos;
    if (!digits || (i == 3 && text.find(',', start) != std::string::npos)) {
      throw GoldenError(origin + " '" + text +
                        "': expected x,y,w,h (four non-negative integers, pixels from the "
                        "top-left corner)");
    }
    *fields[i] = std::stoi(part);
    start = end + 1;
  }
  if (mask.width < 1 || mask.height < 1) {
    throw GoldenError(origin + " '" + text + "': width and height must be at least 1");
  }
  return mask;
}

nlohmann::json tolerance_to_json(const Tolerance& tolerance) {
  nlohmann::json object{{"max_channel_delta", tolerance.max_channel_delta},
                        {"max_differing_pixels", tolerance.max_differing_pixels},
                        {"max_differing_ratio", tolerance.max_differing_ratio},
                        {"window_size", tolerance.window_size},
                        {"max_window_pixels", tolerance.max_window_pixels}};
  if (!tolerance.masks.empty()) {
    nlohmann::json masks = nlohmann::json::array();
    for (const MaskRect& mask : tolerance.masks) {
      masks.push_back({mask.x, mask.y, mask.width, mask.height});
    }
    object["masks"] = std::move(masks);
  }
  return object;
}

}  // namespace impulse2d::golden

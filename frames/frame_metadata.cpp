/// @file frame_metadata.cpp
#include "frames/frame_metadata.h"

#include <iomanip>
#include <sstream>

#include "core/world.h"
#include "frames/version.h"
#include "image/hex_hash.h"

namespace impulse2d::demos {

image::PngText frame_metadata(const std::string& scene, const std::string& parameters,
                               const World& world, const std::string& renderer) {
  namespace keys = image::png_keys;
  std::ostringstream time;
  time << std::setprecision(9) << world.time();
  image::PngText text;
  text[keys::kSoftware] = "impulse2d " + program_version();
  text[keys::kScene] = scene;
  text[keys::kParameters] = parameters.empty() ? "defaults" : parameters;
  text[keys::kStep] = std::to_string(world.step_count());
  text[keys::kTime] = time.str();
  text[keys::kStateHash] = image::to_hex_hash(world.state_hash());
  text[keys::kRenderer] = renderer;
  return text;
}

}  // namespace impulse2d::demos

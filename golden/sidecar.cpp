/// @file sidecar.cpp
#include "golden/sidecar.h"

#include "golden/error.h"
#include "image/file_io.h"
#include "image/hex_hash.h"
#include "golden/json_fields.h"
#include "golden/json_output.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace impulse2d::golden {

using nlohmann::json;

namespace {

/// A pose field as read: the single-precision value it was written from (older sidecars
/// hold the float's exact double, newer ones its shortest decimal form; both give it).
double as_float(double value) { return static_cast<float>(value); }

}  // namespace

RendererFingerprint split_fingerprint(const std::string& fingerprint) {
  const std::string separator = " | ";
  const std::size_t at = fingerprint.find(separator);
  if (at == std::string::npos) return RendererFingerprint{fingerprint, ""};
  return RendererFingerprint{fingerprint.substr(0, at), fingerprint.substr(at + separator.size())};
}

std::string RendererFingerprint::describe() const {
  if (gl_renderer.empty() && gl_version.empty()) return "not recorded";
  return gl_renderer + " / " + gl_version;
}

bool RendererFingerprint::operator==(const RendererFingerprint& other) const {
  return gl_renderer == other.gl_renderer && gl_version == other.gl_version;
}

std::filesystem::path sidecar_path_for(const std::filesystem::path& png) {
  std::filesystem::path sidecar = png;
  sidecar.replace_extension(".json");
  return sidecar;
}

Sidecar sidecar_from_json(const json& object, const std::string& origin) {
  const FieldReader top(object, origin, "");
  top.reject_unknown(
      {"format", "scene", "frame", "width", "height", "state_hash", "renderer", "tolerance",
       "bodies", "noise"});
  const int format = top.integer("format", 1);
  if (format != kSidecarFormat) {
    top.fail("format", "version " + std::to_string(format) + " is not supported (expected " +
                           std::to_string(kSidecarFormat) + ")");
  }
  Sidecar sidecar;
  sidecar.scene = top.string("scene", false);
  sidecar.frame = top.integer("frame", 0);
  sidecar.width = top.integer("width", 1);
  sidecar.height = top.integer("height", 1);
  const std::string hash_text = top.string("state_hash", false);
  const std::optional<std::uint64_t> hash = image::parse_hex_hash(hash_text);
  if (!hash) top.fail("state_hash", "expected 16 hex digits, got \"" + hash_text + "\"");
  sidecar.state_hash = *hash;

  const FieldReader renderer(top.get("renderer"), origin, "renderer.");
  renderer.reject_unknown({"gl_renderer", "gl_version"});
  sidecar.renderer.gl_renderer = renderer.string("gl_renderer", true);
  sidecar.renderer.gl_version = renderer.string("gl_version", true);

  if (top.has("tolerance")) sidecar.tolerance = tolerance_from_json(top.get("tolerance"), origin);

  if (top.has("bodies")) {
    const json& bodies = top.get("bodies");
    if (!bodies.is_array()) top.fail("bodies", "expected an array, got " + bodies.dump());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const FieldReader body(bodies[i], origin, "bodies[" + std::to_string(i) + "].");
      body.reject_unknown({"name", "x", "y", "angle"});
      // Poses are the world's single-precision values, written in their shortest float form.
      sidecar.bodies.push_back({body.string("name", false), as_float(body.number("x")),
                                as_float(body.number("y")), as_float(body.number("angle"))});
    }
  }
  if (top.has("noise")) sidecar.noise = noise_envelope_from_json(top.get("noise"), origin);
  return sidecar;
}

json sidecar_to_json(const Sidecar& sidecar) {
  json bodies = json::array();
  for (const BodyPose& pose : sidecar.bodies) {
    bodies.push_back({{"name", pose.name},
                      {"x", float_for_json(static_cast<float>(pose.x))},
                      {"y", float_for_json(static_cast<float>(pose.y))},
                      {"angle", float_for_json(static_cast<float>(pose.angle))}});
  }
  json object = {{"format", kSidecarFormat},
                 {"scene", sidecar.scene},
                 {"frame", sidecar.frame},
                 {"width", sidecar.width},
                 {"height", sidecar.height},
                 {"state_hash", image::to_hex_hash(sidecar.state_hash)},
                 {"renderer",
                  {{"gl_renderer", sidecar.renderer.gl_renderer},
                   {"gl_version", sidecar.renderer.gl_version}}},
                 {"tolerance", tolerance_to_json(sidecar.tolerance)}};
  if (!sidecar.bodies.empty()) object["bodies"] = std::move(bodies);
  if (!sidecar.noise.empty()) object["noise"] = noise_envelope_to_json(sidecar.noise);
  return object;
}

Sidecar read_sidecar(const std::filesystem::path& file, const std::string& display_name) {
  const std::string origin =
      "sidecar '" + (display_name.empty() ? file.string() : display_name) + "'";
  const std::string text = image::read_text_file(file);
  json object;
  try {
    object = json::parse(text);
  } catch (const json::parse_error& error) {
    throw GoldenError(origin + ": not valid JSON: " + error.what());
  }
  return sidecar_from_json(object, origin);
}

void write_sidecar(const std::filesystem::path& file, const Sidecar& sidecar) {
  const json object = sidecar_to_json(sidecar);
  const std::string text = dump_json_for_file(object, "sidecar '" + file.string() + "'");
  sidecar_from_json(object, "sidecar '" + file.string() + "' (not written)");  // readable back
  image::write_text_file_atomically(file, text);
}

}  // namespace impulse2d::golden

#pragma once
/// @file sidecar.h
/// The JSON file beside each golden PNG (golden_images/<scene>/<name>.json): what produced
/// the image, so a failure can tell a physics change from a rendering change.
///
/// Format (version 1):
/// {
///   "format": 1,
///   "scene": "circles", "frame": 120, "width": 320, "height": 240,
///   "state_hash": "0123456789abcdef",
///   "renderer": {"gl_renderer": "llvmpipe (LLVM 15.0.6, 256 bits)", "gl_version": "4.5 ..."},
///   "tolerance": {"max_channel_delta": 0, ...},            (optional; strict when absent)
///   "bodies": [{"name": "body 0", "x": 0.0, "y": 1.5, "angle": 0.0}, ...],  (optional;
///              single precision, as the world holds them: 11.23 is read as 11.23f)
///   "noise": {...}   the golden's noise envelope (noise_envelope.h)             (optional)
/// }

#include "golden/body_drift.h"
#include "golden/noise_envelope.h"
#include "golden/tolerance.h"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace impulse2d::golden {

/// The OpenGL implementation that drew an image.
struct RendererFingerprint {
  std::string gl_renderer;  ///< glGetString(GL_RENDERER)
  std::string gl_version;   ///< glGetString(GL_VERSION)

  /// "<gl_renderer> / <gl_version>", or "not recorded" when both are empty.
  std::string describe() const;
  /// True when both strings are equal.
  bool operator==(const RendererFingerprint& other) const;
  /// True when either string differs.
  bool operator!=(const RendererFingerprint& other) const { return !(*this == other); }
};

/// "GL_RENDERER | GL_VERSION" (as `render::FrameRenderer::fingerprint` gives it) split into
/// its two strings; without the separator, all of it is the renderer.
RendererFingerprint split_fingerprint(const std::string& fingerprint);

/// Everything recorded beside one golden image.
struct Sidecar {
  std::string scene;              ///< scene name, e.g. "circles"
  int frame = 0;                  ///< steps taken before the frame was drawn
  int width = 0;                  ///< image width, pixels
  int height = 0;                 ///< image height, pixels
  std::uint64_t state_hash = 0;   ///< the world's physics state hash at that frame
  RendererFingerprint renderer;   ///< what drew it
  Tolerance tolerance;            ///< limits the golden is held to (strict by default)
  std::vector<BodyPose> bodies;   ///< body poses at that frame, for drift reports (optional)
  /// How far rounding noise carries the scene up to this frame; empty when not measured
  /// (then a physics change can only be called *simulation diverged*).
  NoiseEnvelope noise;
};

/// The current sidecar format version.
inline constexpr int kSidecarFormat = 1;

/// The sidecar path of a golden or actual PNG: the same path with extension ".json".
std::filesystem::path sidecar_path_for(const std::filesystem::path& png);

/// Validates and converts a parsed sidecar. `origin` names the file in errors and becomes
/// the tolerance's origin, e.g. "sidecar 'circles/start.json'". Throws `GoldenError`
/// naming the origin and the field for missing, unknown, mistyped or out-of-range fields.
Sidecar sidecar_from_json(const nlohmann::json& object, const std::string& origin);

/// The sidecar as JSON, every field written (tolerance included).
nlohmann::json sidecar_to_json(const Sidecar& sidecar);

/// Reads and validates a sidecar file. `display_name` is how errors and tolerance messages
/// name it (default: the path as given). Throws `GoldenError` naming the file and field.
Sidecar read_sidecar(const std::filesystem::path& file, const std::string& display_name = "");

/// Writes a sidecar file atomically (pretty-printed, trailing newline; shortest numbers, body
/// poses as floats). Throws `GoldenError`, writing nothing, for a non-finite number, when
/// `read_sidecar` would reject the result (e.g. an empty scene name) or the write fails.
void write_sidecar(const std::filesystem::path& file, const Sidecar& sidecar);

}  // namespace impulse2d::golden

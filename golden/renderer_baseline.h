#pragma once
/// @file renderer_baseline.h
/// Alternative baselines for other renderers (as VTK keeps `name_1.png`, `name_2.png`): the
/// primary golden `<name>.png` carries the physics (its sidecar's state hash and noise
/// envelope) and the pixels of the renderer that made it; another renderer's pixels live in
/// `<name>@<renderer key>.png` with their own sidecar, beside it.

#include <filesystem>
#include <string>

#include "golden/sidecar.h"

namespace impulse2d::golden {

/// A short file-name-safe key of a renderer: the first word of GL_RENDERER in lower case
/// (letters and digits only) and 8 hex digits of a hash of the whole fingerprint, e.g.
/// "softpipe-1c9e0a4f".
std::string renderer_key(const RendererFingerprint& renderer);

/// `<golden_dir>/<name>@<renderer_key(renderer)>.png`.
std::filesystem::path renderer_baseline_png(const std::filesystem::path& golden_dir,
                                            const std::string& name,
                                            const RendererFingerprint& renderer);

/// The golden a file name found in a golden directory belongs to: "stack/motion" for both
/// "stack/motion" and "stack/motion@softpipe-1c9e0a4f".
std::string baseline_owner(const std::string& name);

}  // namespace impulse2d::golden

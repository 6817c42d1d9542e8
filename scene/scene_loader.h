#pragma once
/// @file scene_loader.h
/// JSON scene files: a user writes a scene without recompiling. The schema is documented in
/// docs/demos.md; every field is validated, and every error names the file, the JSON path and
/// the reason.

#include <string>

#include "scene/scene.h"

namespace impulse2d::demos {

/// Reads and validates the scene file at `path`. Throws `UsageError` "<file>: <json path>:
/// <reason>" for an unreadable file, malformed JSON, an unknown or missing field, a wrong type,
/// a non-finite number, a negative radius or density, a concave or degenerate polygon, an
/// unknown material or option, or an event naming a body that does not exist.
Scene load_scene_file(const std::string& path);

/// As `load_scene_file`, from text already read; `file` names it in messages, and the scene
/// name defaults to its stem.
Scene parse_scene(const std::string& text, const std::string& file);

}  // namespace impulse2d::demos

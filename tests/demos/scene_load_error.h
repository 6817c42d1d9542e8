#pragma once
// The scene-file suites' shared check: the message a scene file's text fails to load with.
#include "scene/scene_loader.h"
#include "scene/usage_error.h"

#include <string>

namespace impulse2d::demos::test {

/// The message `parse_scene` throws for `text` (named "bad.json"), or "" when it loads.
inline std::string load_error(const std::string& text) {
  try {
    parse_scene(text, "bad.json");
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

}  // namespace impulse2d::demos::test

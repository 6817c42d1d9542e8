#pragma once
/// @file scene_registry.h
/// The one list of built-in scenes, shared by the command line, the tests and the benchmarks.
/// Adding a scene: write demos/scenes/<name>.cpp defining `Scene scenes::<name>()` and add
/// the line `IMPULSE2D_SCENE(<name>)` to demos/scenes/scene_list.h.

#include <string>
#include <vector>

#include "scene/scene.h"

namespace impulse2d::demos {

/// Every built-in scene, in the order of demos/scenes/scene_list.h.
const std::vector<Scene>& builtin_scenes();

/// The built-in scene called `name`, or nullptr.
const Scene* find_builtin_scene(const std::string& name);

/// The scene `impulse2d` renders when run without arguments (the first in the list).
const Scene& default_scene();

/// A built-in scene by name, or a scene file when `name_or_path` ends in ".json". Throws
/// `UsageError` for an unknown name (listing the known ones) or an invalid file.
Scene resolve_scene(const std::string& name_or_path);

}  // namespace impulse2d::demos

/// @file scene_registry.cpp
#include "demos/scene_registry.h"

#include "scene/scene_loader.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {

namespace scenes {
#define IMPULSE2D_SCENE(name) Scene name();
#include "demos/scenes/scene_list.h"
#undef IMPULSE2D_SCENE
}  // namespace scenes

const std::vector<Scene>& builtin_scenes() {
  static const std::vector<Scene> all = {
#define IMPULSE2D_SCENE(name) scenes::name(),
#include "demos/scenes/scene_list.h"
#undef IMPULSE2D_SCENE
  };
  return all;
}

const Scene* find_builtin_scene(const std::string& name) {
  for (const Scene& scene : builtin_scenes()) {
    if (scene.name == name) return &scene;
  }
  return nullptr;
}

const Scene& default_scene() { return builtin_scenes().front(); }

Scene resolve_scene(const std::string& name_or_path) {
  const std::string suffix = ".json";
  const bool is_file =
      name_or_path.size() > suffix.size() &&
      name_or_path.compare(name_or_path.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (is_file) return load_scene_file(name_or_path);
  if (const Scene* scene = find_builtin_scene(name_or_path)) return *scene;
  std::string known;
  for (const Scene& scene : builtin_scenes()) known += (known.empty() ? "" : ", ") + scene.name;
  throw UsageError("unknown scene '" + name_or_path + "' (built-in scenes: " + known +
                   "; or give a scene file ending in .json)");
}

}  // namespace impulse2d::demos

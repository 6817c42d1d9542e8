/// @file scene_view.cpp
/// The overlay defaults of a scene view (scene.h).
#include "scene/scene.h"

namespace impulse2d::demos {

DebugDrawOptions default_view_draw() {
  DebugDrawOptions options;
  options.penetration_scale = 10.0f;
  return options;
}

}  // namespace impulse2d::demos

/// @file scene_camera.cpp
#include "demos/scene_camera.h"

#include "demos/scene_run.h"

namespace impulse2d::demos {

render::Camera scene_camera(const CameraSpec& spec, const World& world, int width, int height) {
  const float margin = 0.03f * static_cast<float>(std::min(width, height));
  switch (spec.mode) {
    case CameraSpec::Mode::FitBounds:
      return render::Camera::fit(spec.bounds, width, height, margin);
    case CameraSpec::Mode::Centered:
    case CameraSpec::Mode::Follow:
      return render::Camera::centered(spec.center, spec.pixels_per_metre, width, height);
    case CameraSpec::Mode::FitWorld:
      break;
  }
  return render::Camera::fit(render::world_bounds(world), width, height, margin);
}

render::Camera frame_camera(const render::Camera& camera, const SceneRun& run) {
  const std::optional<vec2> followed = run.followed_position();
  return followed ? camera.with_center(*followed) : camera;
}

}  // namespace impulse2d::demos

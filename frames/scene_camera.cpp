/// @file scene_camera.cpp
#include "frames/scene_camera.h"

#include "scene/scene_run.h"

namespace impulse2d::demos {

namespace {

/// The camera of `spec`'s mode, before its zoom factor.
render::Camera unzoomed_camera(const CameraSpec& spec, const World& world, int width, int height) {
  const float margin = 0.03f * static_cast<float>(std::min(width, height));
  switch (spec.mode) {
    case CameraSpec::Mode::FitBounds:
      return render::Camera::fit(spec.bounds, width, height, margin);
    case CameraSpec::Mode::Follow:
      if (spec.pixels_per_metre <= 0.0f) break;  // the fitted zoom, re-centred every frame
      return render::Camera::centered(spec.center, spec.pixels_per_metre, width, height);
    case CameraSpec::Mode::Centered:
      return render::Camera::centered(spec.center, spec.pixels_per_metre, width, height);
    case CameraSpec::Mode::FitWorld:
      break;
  }
  return render::Camera::fit(render::world_bounds(world), width, height, margin);
}

}  // namespace

render::Camera scene_camera(const CameraSpec& spec, const World& world, int width, int height) {
  const render::Camera camera = unzoomed_camera(spec, world, width, height);
  if (spec.zoom == 1.0f) return camera;
  return render::Camera::centered(camera.center(), camera.pixels_per_metre() * spec.zoom, width, height);
}

render::Camera frame_camera(const render::Camera& camera, const SceneRun& run) {
  const std::optional<vec2> followed = run.followed_position();
  return followed ? camera.with_center(*followed) : camera;
}

}  // namespace impulse2d::demos

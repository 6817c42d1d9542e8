/// @file scene_camera.cpp
#include "frames/scene_camera.h"

#include "render/frame_scale.h"
#include "render/hud_layout.h"
#include "scene/scene_run.h"

#include <algorithm>

namespace impulse2d::demos {

namespace {

/// The HUD and legend bands a width x height image keeps free of the scene: none when they
/// would take more than half of the height.
render::PanelBands kept_bands(int width, int height) {
  const render::PanelBands bands = render::panel_bands(render::frame_scale(width, height));
  if (2.0f * (bands.top + bands.bottom) > static_cast<float>(height)) return render::PanelBands{};
  return bands;
}

/// How far above the image centre (metres) the middle between the bands is, at `zoom`.
vec2 band_shift(int width, int height, float pixels_per_metre) {
  const render::PanelBands bands = kept_bands(width, height);
  return vec2(0.0f, 0.5f * (bands.top - bands.bottom) / pixels_per_metre);
}

/// The camera of `spec`'s mode, before its zoom factor.
render::Camera unzoomed_camera(const CameraSpec& spec, const World& world, int width, int height) {
  const float margin = 0.03f * static_cast<float>(std::min(width, height));
  const render::PanelBands bands = kept_bands(width, height);
  switch (spec.mode) {
    case CameraSpec::Mode::FitBounds:
      return render::Camera::fit_between_bands(spec.bounds, width, height, margin, bands.top, bands.bottom);
    case CameraSpec::Mode::Follow:
      if (spec.pixels_per_metre <= 0.0f) break;  // the fitted zoom, re-centred every frame
      return render::Camera::centered(spec.center + band_shift(width, height, spec.pixels_per_metre),
                                      spec.pixels_per_metre, width, height);
    case CameraSpec::Mode::Centered:
      return render::Camera::centered(spec.center + band_shift(width, height, spec.pixels_per_metre),
                                      spec.pixels_per_metre, width, height);
    case CameraSpec::Mode::FitWorld:
      break;
  }
  return render::Camera::fit_between_bands(render::world_bounds(world), width, height, margin, bands.top,
                                           bands.bottom);
}

}  // namespace

render::Camera scene_camera(const CameraSpec& spec, const World& world, int width, int height) {
  const render::Camera camera = unzoomed_camera(spec, world, width, height);
  if (spec.zoom == 1.0f) return camera;
  // Magnified about the middle between the bands.
  const vec2 middle = camera.center() - band_shift(width, height, camera.pixels_per_metre());
  const float zoom = camera.pixels_per_metre() * spec.zoom;
  return render::Camera::centered(middle + band_shift(width, height, zoom), zoom, width, height);
}

render::Camera run_camera(const SceneRun& run, int width, int height) {
  if (!run.restored()) return scene_camera(run.scene().view.camera, run.world(), width, height);
  const SceneRun fresh(run.scene(), run.params());
  return scene_camera(run.scene().view.camera, fresh.world(), width, height);
}

render::Camera frame_camera(const render::Camera& camera, const SceneRun& run) {
  const std::optional<vec2> followed = run.followed_position();
  if (!followed) return camera;
  return camera.with_center(*followed + band_shift(camera.width(), camera.height(), camera.pixels_per_metre()));
}

}  // namespace impulse2d::demos

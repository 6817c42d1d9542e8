#pragma once
/// @file scene_camera.h
/// The camera of a scene's view for a given image size: it keeps the HUD's band along the top
/// edge and the legend's along the bottom edge free of the scene (`render::panel_bands`).

#include "scene/scene.h"
#include "render/camera.h"

namespace impulse2d::demos {

class SceneRun;

/// The camera `spec` describes for a width x height image, with the scene between the HUD and
/// legend bands of the frame's text scale (`render::frame_scale`; none when the bands would
/// take more than half of the height); `FitWorld` fits `world` as it is now (call it before the
/// first step).
render::Camera scene_camera(const CameraSpec& spec, const World& world, int width, int height);

/// `scene_camera` of `run`'s scene fitted to the world the scene starts from: `run`'s own
/// world before its first step, a fresh run's when `run` continues a saved state (so a
/// resumed run draws its frames exactly as the whole run does).
render::Camera run_camera(const SceneRun& run, int width, int height);

/// The camera for the current frame of `run`: `camera` (from `scene_camera`) moved so that the
/// followed body is in the middle of the space between the bands when the scene's camera
/// follows one, else `camera` unchanged.
render::Camera frame_camera(const render::Camera& camera, const SceneRun& run);

}  // namespace impulse2d::demos

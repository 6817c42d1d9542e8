#pragma once
/// @file scene_camera.h
/// The camera of a scene's view for a given image size.

#include "scene/scene.h"
#include "render/camera.h"

namespace impulse2d::demos {

class SceneRun;

/// The camera `spec` describes for a width x height image; `FitWorld` fits `world` as it is
/// now (call it before the first step).
render::Camera scene_camera(const CameraSpec& spec, const World& world, int width, int height);

/// The camera for the current frame of `run`: `camera` (from `scene_camera`) moved onto the
/// followed body when the scene's camera follows one, else `camera` unchanged.
render::Camera frame_camera(const render::Camera& camera, const SceneRun& run);

}  // namespace impulse2d::demos

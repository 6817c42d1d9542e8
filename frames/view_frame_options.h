#pragma once
/// @file view_frame_options.h
/// A scene view's look (HUD and legend switches, text size, arrow cut, body names, highlight,
/// HUD lines asked for) as the renderer's frame options, for every command that renders.

#include "render/frame_renderer.h"

#include <string>
#include <vector>

namespace impulse2d::demos {

class SceneRun;

/// The frame options of `run`'s scene view with overlays `draw` in `theme`: HUD, legend, text
/// scale, arrow cut, body names for the ids overlay and the scene script's own overlays. Valid
/// while `run` lives. Call `update_view_frame` before each frame.
render::FrameOptions view_frame_options(const SceneRun& run, const DebugDrawOptions& draw, render::Theme theme);

/// Sets what changes from frame to frame: the highlighted body's slot (it may be spawned or
/// removed during the run) and the extra HUD lines (`view_hud_lines`).
void update_view_frame(const SceneRun& run, render::FrameOptions& options, render::HudInfo& hud);

/// The HUD lines the view asks for: the solver settings (`show_settings`) and the last step's
/// per-stage wall-clock times in ms (`show_timings`; they differ from run to run).
std::vector<std::string> view_hud_lines(const SceneRun& run);

}  // namespace impulse2d::demos

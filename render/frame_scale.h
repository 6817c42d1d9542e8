#pragma once
/// @file frame_scale.h
/// How much bigger text, lines and overlay marks are drawn on a large frame, so overlays read
/// the same at 320x240 and at 4000x3000.

namespace impulse2d::render {

/// Shorter frame side, in pixels, per step of `frame_scale`.
constexpr int frame_scale_step_pixels = 480;

/// The integer magnification of text, line widths and overlay marks for a width x height
/// frame (pixels): 1 while the shorter side is below 960 px, then one more per 480 px (2 at
/// 1920x1080, 6 at 4000x3000). Integer, so the bitmap font stays sharp.
int frame_scale(int width, int height);

}  // namespace impulse2d::render

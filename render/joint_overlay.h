#pragma once
/// @file joint_overlay.h
/// The joints overlay as the renderer draws it: `World::draw`'s joint marks (anchors, lines,
/// axes, limits, springs, motors) with the reaction-force arrows cut at the contact arrows'
/// maximum length and marked `//` where cut (`draw_clamped_arrow`).

#include "core/debug_draw.h"

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;

/// Draws the joints of `world` (when `options.flags` has `draw_joints`) with `options`'
/// palette and impulse scale; arrows longer than `max_arrow_pixels` are cut.
void draw_joints_overlay(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                         float max_arrow_pixels);

}  // namespace impulse2d::render

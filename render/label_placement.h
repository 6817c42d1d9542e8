#pragma once
/// @file label_placement.h
/// Text labels put beside a mark (a body's centre-of-mass dot, a contact point) on the side
/// where no other mark goes, at a clearance, so that they never touch it.

#include "core/debug_draw.h"

#include <string>

namespace impulse2d::render {

class PrimitiveRenderer;
struct ScreenRect;

/// The screen rectangle (pixels, y down) of `text` drawn at integer `scale` beside `anchor`
/// (pixels) in the direction `away` (screen, y down; need not be unit, (0, 0) means up and to
/// the right): every point of it lies at least `clearance` pixels from `anchor` along `away`,
/// and its top-left corner is on a whole pixel.
ScreenRect label_rect_beside(vec2 anchor, vec2 away, float clearance, const std::string& text, int scale);

/// Draws `text` in `color` at the renderer's label scale where `label_rect_beside` puts it.
void draw_label_beside(PrimitiveRenderer& renderer, vec2 anchor, vec2 away, float clearance,
                       const std::string& text, Color color);

}  // namespace impulse2d::render

#pragma once
/// @file body_marks.h
/// Marks the renderer puts on bodies: their bounding boxes, their names (or slot indices) and
/// a highlight frame around one chosen body.

#include "core/debug_draw.h"

#include <cstdint>
#include <functional>
#include <string>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;

/// The label of the body in slot `slot`: its name, or empty for the slot index.
using BodyLabeler = std::function<std::string(std::uint32_t slot)>;

/// Colour of the highlight frame (a vivid magenta that no overlay uses).
constexpr Color highlight_color{0.95f, 0.05f, 0.55f, 1.0f};

/// Outlines each living body's bounding box (`Body::aabb`) in `color`, one primitive per
/// box (`World::draw` would draw four segments each for `draw_aabbs`).
void draw_bounding_boxes(PrimitiveRenderer& renderer, const World& world, Color color);

/// Writes each living body's label (`labeler`'s name, else its slot index) beside its drawn
/// centre (interpolated by `options.interpolation_alpha`) in `options.palette.label`: clear of
/// the centre-of-mass dot, on the side away from its velocity arrow (up and to the right at rest).
void draw_body_labels(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                      const BodyLabeler& labeler);

/// Draws a frame `scale` x 3 pixels thick around the bounds of the body in `slot`, 4 x `scale`
/// pixels outside them; nothing when the slot holds no living body.
void draw_highlight(PrimitiveRenderer& renderer, const World& world, std::uint32_t slot, int scale);

}  // namespace impulse2d::render

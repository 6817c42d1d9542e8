#pragma once
/// @file island_overlay.h
/// Island colours (Box2D's constraint-graph view): dynamic bodies joined by touching contacts
/// form an island; each island gets a colour, drawn as a dot on its bodies' centres and a line
/// along each of its contacts.

#include "core/debug_draw.h"

#include <cstdint>
#include <vector>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;

/// The island of every world slot up to the last living body's: dynamic bodies connected
/// through enabled contacts share a number (0, 1, ... in order of their lowest slot); static,
/// kinematic and dead slots are -1 (they never join islands, as in Box2D).
std::vector<int> island_of_slots(const World& world);

/// The colour of island `island` (cycles through 8 distinct colours).
Color island_color(int island);

/// Draws each island in its colour: a line from body to body (or to the contact point, for a
/// contact with a non-dynamic body) per enabled contact, and a dot of 5 pixels at frame scale 1
/// (`PrimitiveStyle::point_scale` scales it) on each dynamic body's centre.
void draw_islands(PrimitiveRenderer& renderer, const World& world);

}  // namespace impulse2d::render

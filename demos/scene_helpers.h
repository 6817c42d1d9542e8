#pragma once
/// @file scene_helpers.h
/// Small building blocks shared by the built-in scene builders.

#include <cstdint>

#include "core/body.h"
#include "core/shape.h"
#include "demos/scene_random.h"

namespace impulse2d {
class World;
}

namespace impulse2d::demos {

/// Creates a body of `type` with `shape` at `position` (metres) and `angle` (radians) made of
/// `material`, colliding with `layers`. Returns its handle.
BodyId add_body(World& world, BodyType type, const Shape& shape, vec2 position,
                const Material& material, float angle = 0.0f, std::uint32_t layers = 1u);

/// A static axis-aligned box centred at `center` with `half_extents` (metres).
BodyId add_static_box(World& world, vec2 center, vec2 half_extents, const Material& material,
                      std::uint32_t layers = 1u);

/// A convex polygon of 3..8 vertices on a circle of `radius` metres, one vertex in each of
/// `count` equal sectors at a random place inside the middle 70% of its sector (so no two
/// vertices come close and the outline is always convex).
Shape random_convex_polygon(SceneRandom& random, float radius);

/// `material` with both friction coefficients set to zero (and "(frictionless)" in its name).
Material frictionless(Material material);

/// The box from `lower` to `upper` (metres).
Aabb make_bounds(vec2 lower, vec2 upper);

/// Degrees to radians.
float radians(float degrees);

}  // namespace impulse2d::demos

#pragma once
/// @file primitive_shaders.h
/// GLSL 3.30 sources of the one program that draws every primitive of a frame. The CPU
/// expands each primitive into a quad in window pixels; each vertex carries its position,
/// its offset from the primitive's centre, the primitive's extent and its colour, and the
/// fragment stage turns those into analytic coverage:
///   extent.x >= 0: a rectangle of half sizes `extent` (segments; solid shapes use a huge
///                  extent, so coverage is 1),
///   extent.x < 0:  a disc of radius -extent.x, or a ring of width extent.y when > 0.

namespace impulse2d::render {

/// Vertex stage: window pixels to clip space; passes offset, extent and colour on.
extern const char* const primitive_vertex_shader;
/// Fragment stage: coverage of the rectangle or disc multiplied into alpha.
extern const char* const primitive_fragment_shader;

}  // namespace impulse2d::render

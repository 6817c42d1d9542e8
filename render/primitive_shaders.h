#pragma once
/// @file primitive_shaders.h
/// GLSL 3.30 sources of the one program that draws every primitive of a frame: each
/// instance is six vertices (two triangles) whose meaning depends on its kind.

namespace impulse2d::render {

/// What one primitive instance is; the numbers are shared with the shaders.
enum class PrimitiveKind : unsigned int {
  Triangle = 0,       ///< p0, p1, p2: world corners; no anti-aliasing (an outline covers edges)
  Parallelogram = 1,  ///< p0, p1, p2: consecutive world corners, the fourth is p0 + p2 - p1
  Segment = 2,        ///< p0 -> p1 world; params: half width, end extension (pixels)
  Disc = 3,           ///< p0 world centre; params: radius, ring width (0 = solid) (pixels)
  AnchoredRect = 4,   ///< p0 world anchor snapped to a pixel; p1, p2: rectangle offsets (pixels, y up)
  ScreenRect = 5,     ///< p1, p2: rectangle corners in GL window pixels (y up)
};

/// Vertex stage: expands an instance to screen pixels, then to clip space.
extern const char* const primitive_vertex_shader;
/// Fragment stage: analytic coverage of segments and discs multiplied into alpha.
extern const char* const primitive_fragment_shader;

}  // namespace impulse2d::render

#pragma once
/// @file primitive_shaders.h
/// GLSL 3.30 sources of the programs that draw the primitives of a frame, one program per
/// primitive kind. Each primitive (but the fill triangles of polygons with more edges than
/// a polygon primitive has) is one point sprite (or, when large, a quad of four
/// vertices) covering it; all its parameters are flat, and the fragment stage measures the
/// pixel centre (`gl_FragCoord`) in the primitive's own frame, so a primitive gives the same
/// pixels whichever way it is rasterised. Attributes (see `PrimitiveRenderer::Vertex`):
///   sprite: window position of the point or quad corner, point size;
///   frame:  origin (window pixels) and unit x axis of the primitive's frame;
///   box:    half extents (x, y) of a rectangle centred on the origin; width of a
///           rectangle's outline (w; 0: filled);
///   head:   an arrow head along +x: base x, tip x (it ends there), outward normal of its
///           upper side;
///   disc:   a disc's radius and a ring's outer and inner radii, centred on the origin;
///   fill:   colour of the rectangle, head and disc; line: colour of the ring.
/// A polygon's vertex has sprite, fill and line as above, its origin (window pixels) with half
/// its outline's width, and up to 8 edges as outward unit normal and offset from the origin;
/// its distance to a pixel centre is the largest of the edges' (a mitred outline).
/// A text run's vertex has sprite and fill as above, the run's top-left corner and size
/// (window pixels), font pixels per window pixel, and the run's font pixels as 256 bits
/// (bit column * font_glyph_rows + row, low word first).
/// A disc's or polygon's fill is composited under its ring or outline in the shader, and the premultiplied result
/// blended over the framebuffer once.

#include <string>

namespace impulse2d::render {

/// What a primitive is, and so which fragment program measures its coverage. llvmpipe
/// runs every branch of a shader on every 4x4 pixel block, so each kind has a program
/// that computes only its own shape.
enum class PrimitiveKind {
  polygon,  ///< convex polygon of up to `polygon_primitive_edges` edges with its outline
  solid,    ///< fill triangles of larger polygons: coverage 1
  disc,   ///< disc with an optional ring (circles, dots)
  box,    ///< rectangle or rectangle outline in its own frame (segments, bars, panels)
  arrow,  ///< shaft rectangle and triangular head
  text,   ///< a run of characters of the bitmap font, up to `text_run_columns` font pixels wide
};

/// Number of `PrimitiveKind`s.
constexpr int primitive_kind_count = 6;
/// Most edges of one `PrimitiveKind::polygon` (core's `max_polygon_vertices`).
constexpr int polygon_primitive_edges = 8;
/// Most font pixel columns of one `PrimitiveKind::text` run: 256 bits of 9-pixel columns.
constexpr int text_run_columns = 28;

/// Vertex stage of `kind`: window pixels to clip space and point size; passes the parameters
/// on flat.
const char* primitive_vertex_shader(PrimitiveKind kind);
/// Fragment stage of `kind`: analytic anti-aliased coverage of that shape, composited colour.
std::string primitive_fragment_shader(PrimitiveKind kind);

}  // namespace impulse2d::render

#pragma once
/// @file primitive_shaders.h
/// GLSL 3.30 sources of the one program that draws every primitive of a frame. Each
/// primitive is one point sprite (or, when large, a quad of four vertices) covering it; all
/// its parameters are flat, and the fragment stage measures the pixel centre
/// (`gl_FragCoord`) in the primitive's own frame, so a primitive gives the same pixels
/// whichever way it is rasterised. Attributes (see `PrimitiveRenderer::Vertex`):
///   sprite: window position of the point or quad corner, point size;
///   frame:  origin (window pixels) and unit x axis of the primitive's frame;
///   box:    half extents of a rectangle centred on the origin (negative: none) and, for a
///           glyph, font pixels per window pixel (0: not a glyph);
///   head:   an arrow head along +x: base x, tip x (it ends there), outward normal of its
///           upper side;
///   disc:   x offset of a disc's centre, its radius, and a ring's outer and inner radii;
///   fill:   colour of the rectangle, head, disc and glyph; line: colour of the ring;
///   glyph:  font_glyph_columns x font_glyph_rows bitmap, low word first.
/// The fill layer is composited under the ring layer in the shader, and the premultiplied
/// result blended over the framebuffer once.

namespace impulse2d::render {

/// Vertex stage: window pixels to clip space and point size; passes the parameters on flat.
extern const char* const primitive_vertex_shader;
/// Fragment stage: analytic anti-aliased coverage of the primitive, composited colour.
extern const char* const primitive_fragment_shader;

}  // namespace impulse2d::render

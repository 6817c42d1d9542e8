#pragma once
/// @file primitive_vertices.h
/// The parameters of one primitive as the fragment programs of primitive_shaders.h read
/// them (one vertex of a point sprite or quad corner), shared by the GL batches and the CPU
/// rasteriser (software_raster.h), which evaluates the same coverage formulas.

#include "render/primitive_shaders.h"

#include <cstdint>

namespace impulse2d::render {

/// One vertex of the disc, box, arrow and fill-triangle kinds (see primitive_shaders.h). The
/// defaults switch every shape off.
struct ShapeVertex {
  float sprite[3] = {0.0f, 0.0f, 1.0f};           ///< window position (pixels, y up), point size
  float frame[4] = {0.0f, 0.0f, 1.0f, 0.0f};      ///< origin (window pixels), unit x axis
  float box[4] = {-1.0e6f, -1.0e6f, 0.0f, 0.0f};  ///< half extents; w: outline width (0: filled)
  float head[4] = {1.0e6f, 0.0f, 0.0f, 0.0f};     ///< arrow head base x, tip x, upper side's normal
  float disc[3] = {-1.0e6f, -1.0e6f, -1.0e6f};    ///< disc radius, ring outer and inner radii (pixels)
  std::uint8_t fill[4] = {0, 0, 0, 0};            ///< colour of the rectangle, head and disc
  std::uint8_t line[4] = {0, 0, 0, 0};            ///< colour of the ring
};

/// One vertex of the polygon kind. Unused edges never bound the polygon.
struct PolygonVertex {
  float sprite[3] = {0.0f, 0.0f, 1.0f};  ///< window position (pixels, y up), point size
  float origin[3] = {0.0f, 0.0f, 0.0f};  ///< window pixels; half the outline's width
  float edges[polygon_primitive_edges][3] = {};  ///< outward unit normal, offset from the origin
  std::uint8_t fill[4] = {0, 0, 0, 0};           ///< colour of the fill
  std::uint8_t line[4] = {0, 0, 0, 0};           ///< colour of the outline
};

/// One vertex of the text kind: a run of characters of one line.
struct TextVertex {
  float sprite[3] = {0.0f, 0.0f, 1.0f};     ///< window position (pixels, y up), point size
  float run[4] = {0.0f, 0.0f, 0.0f, 0.0f};  ///< top-left corner, width and height (window pixels)
  float font_scale = 1.0f;                  ///< font pixels per window pixel
  std::uint8_t fill[4] = {0, 0, 0, 0};      ///< colour of the text
  std::uint32_t bits[8] = {};  ///< font pixel (column, row) is bit column * font_glyph_rows + row
};

}  // namespace impulse2d::render

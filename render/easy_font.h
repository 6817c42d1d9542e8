#pragma once
/// @file easy_font.h
/// Text from stb_easy_font (a public-domain bitmap font built of quads): as rectangles, and
/// as one bitmap per character for drawing each character as a single primitive.

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::render {

/// One filled rectangle of a glyph, in font pixels relative to the text's top-left corner
/// (x right, y down).
struct GlyphRect {
  float left = 0.0f;    ///< minimum x
  float top = 0.0f;     ///< minimum y
  float right = 0.0f;   ///< maximum x
  float bottom = 0.0f;  ///< maximum y
};

/// Height of a capital letter in font pixels: a line's baseline is this far below its top.
constexpr float font_cap_height = 7.0f;

/// Distance between the tops of consecutive lines, font pixels (stb_easy_font's).
constexpr float font_line_height = 12.0f;

/// Columns of a glyph bitmap: every character's rectangles lie in x = 0..7 font pixels.
constexpr int font_glyph_columns = 7;
/// Rows of a glyph bitmap: every character's rectangles lie in y = 0..9 font pixels.
constexpr int font_glyph_rows = 9;

/// One character rasterised from its rectangles: bit (row * font_glyph_columns + column)
/// is set when font pixel (column, row) of the cell (y down from the text line's top) is
/// covered. Pen advance is the x distance to the next character, font pixels.
struct GlyphBitmap {
  std::uint64_t bits = 0;  ///< font_glyph_columns x font_glyph_rows cells, row-major
  /// The same cells by column: bit `row` of `columns[column]` is bit (row * font_glyph_columns
  /// + column) of `bits`.
  std::uint16_t columns[font_glyph_columns] = {};
  int advance = 0;         ///< font pixels from this character's left edge to the next one's
  int ink_left = 0;        ///< first column with a set bit
  int ink_top = 0;         ///< first row with a set bit
  int ink_right = 0;       ///< one past the last column with a set bit
  int ink_bottom = 0;      ///< one past the last row with a set bit
};

/// The bitmap of `character`; characters outside printable ASCII (32..126) have no pixels
/// and no advance.
const GlyphBitmap& glyph_bitmap(char character);

/// Appends the rectangles that draw `text` (ASCII; '\n' starts a new line) to `rects`.
void layout_text(const std::string& text, std::vector<GlyphRect>& rects);

/// Width of the widest line of `text`, font pixels.
float text_width(const std::string& text);

/// Height of `text` (12 font pixels per line), font pixels.
float text_height(const std::string& text);

}  // namespace impulse2d::render

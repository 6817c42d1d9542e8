#pragma once
/// @file easy_font.h
/// Text as rectangles, from stb_easy_font (a public-domain bitmap font built of quads).

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

/// Appends the rectangles that draw `text` (ASCII; '\n' starts a new line) to `rects`.
void layout_text(const std::string& text, std::vector<GlyphRect>& rects);

/// Width of the widest line of `text`, font pixels.
float text_width(const std::string& text);

/// Height of `text` (12 font pixels per line), font pixels.
float text_height(const std::string& text);

}  // namespace impulse2d::render

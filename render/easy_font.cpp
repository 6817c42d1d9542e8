/// @file easy_font.cpp
/// The only file that includes stb_easy_font.h (its functions are static to this file).
#include "render/easy_font.h"

#include <stb_easy_font.h>

#include <algorithm>
#include <array>

namespace impulse2d::render {

namespace {

// stb_easy_font emits four vertices per quad: x, y, z (floats) and an RGBA colour.
struct EasyFontVertex {
  float x;
  float y;
  float z;
  unsigned char color[4];
};

}  // namespace

void layout_text(const std::string& text, std::vector<GlyphRect>& rects) {
  if (text.empty()) return;
  // stb's estimate is ~270 bytes per character; leave room for the densest glyphs.
  thread_local std::vector<EasyFontVertex> vertices;
  vertices.resize(text.size() * 64 + 64);
  std::string mutable_text = text;  // stb takes a non-const char*
  const int quads = stb_easy_font_print(0.0f, 0.0f, mutable_text.data(), nullptr, vertices.data(),
                                        static_cast<int>(vertices.size() * sizeof(EasyFontVertex)));
  for (int q = 0; q < quads; ++q) {
    const EasyFontVertex* v = &vertices[static_cast<std::size_t>(q) * 4];
    GlyphRect rect{v[0].x, v[0].y, v[0].x, v[0].y};
    for (int i = 1; i < 4; ++i) {
      rect.left = std::min(rect.left, v[i].x);
      rect.right = std::max(rect.right, v[i].x);
      rect.top = std::min(rect.top, v[i].y);
      rect.bottom = std::max(rect.bottom, v[i].y);
    }
    rects.push_back(rect);
  }
}

const GlyphBitmap& glyph_bitmap(char character) {
  static const std::array<GlyphBitmap, 128> bitmaps = [] {
    std::array<GlyphBitmap, 128> table{};
    std::vector<GlyphRect> rects;
    for (int code = 32; code < 127; ++code) {
      const std::string text(1, static_cast<char>(code));
      rects.clear();
      layout_text(text, rects);
      GlyphBitmap& glyph = table[static_cast<std::size_t>(code)];
      glyph.advance = static_cast<int>(text_width(text));
      for (int row = 0; row < font_glyph_rows; ++row) {
        for (int column = 0; column < font_glyph_columns; ++column) {
          const float x = static_cast<float>(column) + 0.5f;  // font pixel centre
          const float y = static_cast<float>(row) + 0.5f;
          for (const GlyphRect& rect : rects) {
            if (x > rect.left && x < rect.right && y > rect.top && y < rect.bottom) {
              if (glyph.bits == 0) {
                glyph.ink_left = glyph.ink_right = column;
                glyph.ink_top = row;
              }
              glyph.bits |= std::uint64_t{1} << (row * font_glyph_columns + column);
              glyph.columns[column] = static_cast<std::uint16_t>(glyph.columns[column] | (1u << row));
              glyph.ink_left = std::min(glyph.ink_left, column);
              glyph.ink_right = std::max(glyph.ink_right, column + 1);
              glyph.ink_bottom = row + 1;
              break;
            }
          }
        }
      }
    }
    return table;
  }();
  const auto code = static_cast<unsigned char>(character);
  return bitmaps[code < bitmaps.size() ? code : 0];
}

float text_width(const std::string& text) {
  std::string mutable_text = text;
  return static_cast<float>(stb_easy_font_width(mutable_text.data()));
}

float text_height(const std::string& text) {
  std::string mutable_text = text;
  return static_cast<float>(stb_easy_font_height(mutable_text.data()));
}

}  // namespace impulse2d::render

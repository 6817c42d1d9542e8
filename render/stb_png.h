#pragma once
/// @file stb_png.h
/// The two stb_image_write instances behind `encode_png`. Each lives in its own translation
/// unit (stb_png_fast.cpp, stb_png_default.cpp) with stb compiled static, because the deflate
/// function is chosen at compile time and stb's settings are file-level variables.

#include <cstdint>
#include <vector>

namespace impulse2d::render::detail {

/// PNG of a top-down RGBA8 image with libdeflate level 1 and a fixed row filter. Returns
/// false when stb or libdeflate fails. Thread-safe.
bool stb_png_fast(const std::uint8_t* rgba, int width, int height, std::vector<std::uint8_t>& png);

/// PNG of a top-down RGBA8 image with stb's default deflate and filter search. Returns false
/// when stb fails. Thread-safe.
bool stb_png_default(const std::uint8_t* rgba, int width, int height, std::vector<std::uint8_t>& png);

}  // namespace impulse2d::render::detail

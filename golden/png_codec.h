#pragma once
/// @file png_codec.h
/// PNG bytes <-> RGBA8 pixels. The only file that sees stb_image; its functions are
/// internal to png_codec.cpp so another library's copy of stb cannot clash with ours.

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::golden {

struct Image;

/// Decodes PNG bytes to RGBA8 after `png_structure_problem` found none. Returns false and
/// sets `error` to the structural problem or stb's reason on failure.
bool decode_png_bytes(const std::vector<std::uint8_t>& bytes, Image& image, std::string& error);

/// Encodes RGBA8 pixels as PNG bytes (zlib level 9). Returns an empty vector on failure.
std::vector<std::uint8_t> encode_png_bytes(const Image& image);

}  // namespace impulse2d::golden

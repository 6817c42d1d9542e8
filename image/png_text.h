#pragma once
/// @file png_text.h
/// Text metadata in PNG files (tEXt chunks): what produced a frame (scene, parameters, step,
/// simulated time, physics state hash, renderer, program version), so `impulse2d diff` can
/// classify two frames from two builds without a sidecar.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace impulse2d::image {

/// Keyword -> text of a PNG's tEXt chunks (Latin-1; keywords 1..79 characters).
using PngText = std::map<std::string, std::string>;

/// The keywords the golden tools write.
namespace png_keys {
inline constexpr const char* kSoftware = "Software";                   ///< "impulse2d 0.1.0"
inline constexpr const char* kScene = "impulse2d scene";               ///< scene name (and file)
inline constexpr const char* kParameters = "impulse2d parameters";     ///< "rows=8 seed=3"
inline constexpr const char* kStep = "impulse2d step";                 ///< steps simulated
inline constexpr const char* kTime = "impulse2d simulated time";       ///< seconds
inline constexpr const char* kStateHash = "impulse2d state hash";      ///< 16 hex digits
inline constexpr const char* kRenderer = "impulse2d renderer";         ///< GL_RENDERER / GL_VERSION
}  // namespace png_keys

/// `png` (a well-formed PNG) with one tEXt chunk per entry inserted right after IHDR.
/// Throws `ImageError` for an empty or over-long keyword, or a keyword or text holding a
/// NUL byte.
std::vector<std::uint8_t> with_png_text(const std::vector<std::uint8_t>& png, const PngText& text);

/// The tEXt chunks of a well-formed PNG (`png_structure_problem` found none); a keyword
/// that repeats keeps its first text.
PngText read_png_text(const std::vector<std::uint8_t>& png);

}  // namespace impulse2d::image

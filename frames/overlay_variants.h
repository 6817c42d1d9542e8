#pragma once
/// @file overlay_variants.h
/// The browser viewer's overlay switch: besides the frames with every chosen overlay, `render
/// --html` renders each frame again with no overlay and, when more than one overlay group is
/// chosen, with each group alone, into `<scene>.overlays/<variant>/` beside the frames, so that
/// the page switches between them without a new render.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// One pre-rendered variant of a frame sequence.
struct OverlayVariant {
  std::string name;          ///< "none" or an overlay name as `--overlays` takes it
  std::uint32_t flags = 0;   ///< the `DebugDrawFlag`s it is rendered with
};

/// The variants of frames drawn with `flags`: none when no overlay group is on; "none"
/// (shapes only) and, with two or more groups, each group alone ("contacts" and "all" count as
/// their parts). Flags that are not overlay groups (shapes) are kept in every variant.
std::vector<OverlayVariant> overlay_variants(std::uint32_t flags);

/// `directory/<scene>.overlays`, where the variants' frames go.
std::filesystem::path overlay_variants_path(const std::filesystem::path& directory,
                                            const std::string& scene);

}  // namespace impulse2d::demos

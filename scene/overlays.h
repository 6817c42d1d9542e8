#pragma once
/// @file overlays.h
/// Overlay names as the command line and scene files spell them, and their draw flags.

#include <cstdint>
#include <string>
#include <vector>

namespace impulse2d::demos {

/// One named overlay.
struct OverlayName {
  const char* name;         ///< e.g. "normals"
  std::uint32_t flags;      ///< the `DebugDrawFlag`s it turns on
  const char* description;  ///< for --help
};

/// Every overlay name, in the order `--help` lists them ("all" last).
const std::vector<OverlayName>& overlay_names();

/// The flags of a comma-separated list such as "normals,impulses" or "all" (shapes are always
/// drawn; "none" or an empty list means shapes only). Throws `UsageError` naming an unknown
/// entry and listing the known ones.
std::uint32_t parse_overlays(const std::string& list);

/// The flags of one overlay name (see `parse_overlays`).
std::uint32_t overlay_flags(const std::string& name);

}  // namespace impulse2d::demos

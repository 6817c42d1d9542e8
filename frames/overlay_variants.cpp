/// @file overlay_variants.cpp
#include "frames/overlay_variants.h"

#include "frames/contact_sheet.h"

namespace impulse2d::demos {

std::vector<OverlayVariant> overlay_variants(std::uint32_t flags) {
  const std::vector<OverlayName> groups = overlay_cover(flags, false);
  if (groups.empty()) return {};
  std::uint32_t group_flags = 0;
  for (const OverlayName& group : groups) group_flags |= group.flags;
  const std::uint32_t base = flags & ~group_flags;
  std::vector<OverlayVariant> variants = {{"none", base}};
  if (groups.size() < 2) return variants;
  for (const OverlayName& group : groups) variants.push_back({group.name, base | group.flags});
  return variants;
}

std::filesystem::path overlay_variants_path(const std::filesystem::path& directory,
                                            const std::string& scene) {
  return directory / (scene + ".overlays");
}

}  // namespace impulse2d::demos

#pragma once
/// @file contact_sheet.h
/// A contact sheet: chosen frames of a run tiled into one PNG, each tile framed by a border
/// and separated from its neighbours by a gutter, with a label strip (step and simulated
/// time) under it and a title over the whole sheet (scene, parameters, overlays, trails).

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/debug_draw.h"
#include "frames/frame_plan.h"
#include "scene/overlays.h"
#include "scene/scene_run.h"
#include "frames/trail_selection.h"
#include "render/palette.h"

namespace impulse2d::demos {

/// Layout and looks of a contact sheet.
struct ContactSheetOptions {
  int tile_width = 400;                        ///< pixels per frame
  int tile_height = 300;                       ///< pixels per frame
  int columns = 4;                             ///< tiles per row (>= 1)
  render::Theme theme = render::Theme::Light;  ///< colours
  TrailSelection trails;                       ///< bodies whose recent path is drawn
  std::string caption;  ///< the title's second line, e.g. "rows=20 | overlays: normals"
};

/// The size in pixels {width, height} of a sheet of `frame_count` tiles laid out as `options`
/// say. Throws `UsageError` for columns < 1, or when the sheet would exceed the limits of
/// run_limits.h (naming the sizes and what to change) — before anything is rendered.
std::pair<int, int> contact_sheet_size(int frame_count, const ContactSheetOptions& options);

/// One scene's part of a contact sheet: its run (built, not yet stepped), the steps shown and
/// the overlays they are drawn with.
struct SheetSource {
  SceneRun* run = nullptr;  ///< stepped forward through `plan` while the tiles are drawn
  FramePlan plan;           ///< the steps shown, one tile each
  DebugDrawOptions draw;    ///< overlay flags and arrow scales of its tiles
};

/// Steps each source's run through its plan, renders each planned step as a tile, in the
/// sources' order, and writes the sheet to `output` (atomically; a directory it had to create
/// is removed again on failure). A source's tiles share one camera: its scene's, moved
/// vertically so that what it shows of the bodies over the planned frames is centred (found
/// on a second run of the same scene, stepped first). With several sources each label names
/// its scene and the title counts them. Returns the sheet's size in pixels as {width, height}.
std::pair<int, int> write_contact_sheet(const std::vector<SheetSource>& sources,
                                        const ContactSheetOptions& options,
                                        const std::filesystem::path& output);

/// The overlay names (as `--overlays` takes them, in its order) that together draw `flags`,
/// the widest names first ("contacts" rather than its four parts); without `composites`,
/// "contacts" and "all" are not used (their parts are). Empty for 0.
std::vector<OverlayName> overlay_cover(std::uint32_t flags, bool composites);

/// "normals, penetration" for a set of `DebugDrawFlag`s, by the overlay names `--overlays`
/// takes (the widest names first: "contacts" rather than its four parts); "none" when no
/// overlay is on (shapes alone, or 0).
std::string overlay_list(std::uint32_t flags);

}  // namespace impulse2d::demos

#pragma once
/// @file contact_sheet.h
/// A contact sheet: chosen frames of a run tiled into one PNG, each with a label strip
/// (step and simulated time) and a title strip over the whole sheet.

#include <cstdint>
#include <filesystem>

#include "core/debug_draw.h"
#include "demos/frame_plan.h"
#include "demos/scene_run.h"
#include "render/palette.h"

namespace impulse2d::demos {

/// Layout and looks of a contact sheet.
struct ContactSheetOptions {
  int tile_width = 400;                        ///< pixels per frame
  int tile_height = 300;                       ///< pixels per frame
  int columns = 4;                             ///< tiles per row (>= 1)
  DebugDrawOptions draw;                       ///< overlay flags and arrow scales
  render::Theme theme = render::Theme::Light;  ///< colours
};

/// Steps `run` through `plan`, renders each planned step as a tile and writes the sheet to
/// `output` (atomically; a directory it had to create is removed again on failure).
/// Returns the sheet's size in pixels as {width, height}.
std::pair<int, int> write_contact_sheet(SceneRun& run, const FramePlan& plan,
                                        const ContactSheetOptions& options,
                                        const std::filesystem::path& output);

}  // namespace impulse2d::demos

/// @file contact_sheet.cpp
#include "demos/contact_sheet.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "demos/frame_sequence.h"
#include "demos/output_guard.h"
#include "demos/run_limits.h"
#include "demos/scene_camera.h"
#include "demos/view_frame_options.h"
#include "scene/usage_error.h"
#include "render/frame_renderer.h"
#include "render/png_encoder.h"

namespace impulse2d::demos {
namespace {

constexpr int label_height = 22;  // pixels under each tile
constexpr int title_height = 30;  // pixels over the sheet
constexpr int text_scale = 2;     // magnification of the 7-pixel font in labels

/// Copies `tile` into `sheet` with its top-left corner at (x, y).
void paste(const render::Frame& tile, render::Frame& sheet, int x, int y) {
  for (int row = 0; row < tile.height; ++row) {
    std::memcpy(
        &sheet.rgba[(static_cast<std::size_t>(y + row) * static_cast<std::size_t>(sheet.width) +
                     static_cast<std::size_t>(x)) *
                    4],
        &tile.rgba[static_cast<std::size_t>(row) * tile.stride()], tile.stride());
  }
}

std::string step_label(std::int64_t step, double time) {
  char text[64];
  std::snprintf(text, sizeof text, "step %lld   t = %.2f s", static_cast<long long>(step), time);
  return text;
}

}  // namespace

std::pair<int, int> write_contact_sheet(SceneRun& run, const FramePlan& plan,
                                        const ContactSheetOptions& options,
                                        const std::filesystem::path& output) {
  if (options.columns < 1) throw UsageError("--columns must be >= 1");
  const int count = static_cast<int>(plan.frames.size());
  const int columns = std::min(options.columns, count);
  const int rows = (count + columns - 1) / columns;
  const int cell_height = options.tile_height + label_height;
  const std::int64_t width64 = static_cast<std::int64_t>(columns) * options.tile_width;
  const std::int64_t height64 = title_height + static_cast<std::int64_t>(rows) * cell_height;
  if (width64 > limits::max_sheet_side || height64 > limits::max_sheet_side ||
      width64 * height64 > limits::max_sheet_pixels) {
    throw UsageError("sheet: " + std::to_string(count) + " tiles of " +
                     std::to_string(options.tile_width) + "x" + std::to_string(options.tile_height) +
                     " in " + std::to_string(columns) + " columns make a " +
                     std::to_string(width64) + "x" + std::to_string(height64) +
                     " sheet; the limits are " + std::to_string(limits::max_sheet_side) +
                     " pixels a side and " + std::to_string(limits::max_sheet_pixels) +
                     " pixels in all (use a smaller --tile, fewer frames or other --columns)");
  }
  const int width = static_cast<int>(width64);
  const int height = static_cast<int>(height64);

  render::FrameRenderer tiles(options.tile_width, options.tile_height);
  const render::Camera camera =
      scene_camera(run.scene().view.camera, run.world(), options.tile_width, options.tile_height);
  render::FrameOptions frame_options = view_frame_options(run, options.draw, options.theme);
  frame_options.show_hud = false;  // the label strip says it
  const render::ThemePalette palette = render::theme_palette(options.theme);

  // Render every tile first (the simulation runs forward once), remembering its label.
  std::vector<render::Frame> frames;
  std::vector<std::string> labels;
  for (const std::int64_t step : plan.frames) {
    while (run.step_count() < step) run.step();
    frame_options.show_legend = frames.empty() && run.scene().view.show_legend;  // on the first tile
    render::HudInfo hud;
    update_view_frame(run, frame_options, hud);
    frames.push_back(tiles.render(run.world(), frame_camera(camera, run), frame_options, hud));
    labels.push_back(step_label(step, run.world().time()));
  }

  // Background, title and labels in one pass over the whole sheet, then the tiles on top.
  render::FrameRenderer sheet_renderer(width, height);
  const render::Camera sheet_camera = render::Camera::centered({0.0f, 0.0f}, 1.0f, width, height);
  render::Frame sheet;
  sheet_renderer.render_primitives(
      sheet_camera, palette.background,
      [&](render::PrimitiveRenderer& draw) {
        draw.draw_screen_rect({0.0f, 0.0f},
                              {static_cast<float>(width), static_cast<float>(title_height)},
                              palette.hud_panel);
        draw.draw_screen_text({8.0f, 8.0f}, scene_title(run.scene()), palette.hud_text, text_scale);
        for (int i = 0; i < count; ++i) {
          const float x = static_cast<float>((i % columns) * options.tile_width);
          const float y =
              static_cast<float>(title_height + (i / columns) * cell_height + options.tile_height);
          draw.draw_screen_text({x + 8.0f, y + 4.0f}, labels[static_cast<std::size_t>(i)],
                                palette.hud_text, text_scale);
        }
      },
      sheet);
  for (int i = 0; i < count; ++i) {
    paste(frames[static_cast<std::size_t>(i)], sheet, (i % columns) * options.tile_width,
          title_height + (i / columns) * cell_height);
  }

  OutputGuard guard;
  if (!output.parent_path().empty()) {
    guard.will_create_directory(output.parent_path());
    std::filesystem::create_directories(output.parent_path());
  }
  render::write_png(output, sheet);
  guard.commit();
  return {width, height};
}

}  // namespace impulse2d::demos

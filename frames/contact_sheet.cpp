/// @file contact_sheet.cpp
#include "frames/contact_sheet.h"

#include <algorithm>
#include <bitset>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/shape.h"
#include "core/world.h"
#include "frames/frame_sequence.h"
#include "frames/output_guard.h"
#include "scene/run_limits.h"
#include "frames/scene_camera.h"
#include "frames/view_frame_options.h"
#include "render/event_marks.h"
#include "render/frame_renderer.h"
#include "render/motion_trails.h"
#include "image/png.h"
#include "scene/overlays.h"
#include "scene/usage_error.h"

namespace impulse2d::demos {
namespace {

constexpr int gutter = 10;        // pixels between tiles and around the sheet
constexpr int label_height = 22;  // pixels under each tile
constexpr int title_height = 50;  // pixels over the sheet: the title and its caption
constexpr int text_scale = 2;     // magnification of the 7-pixel font in the title and labels

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

/// The top-left pixel of tile `index`.
std::pair<int, int> tile_origin(int index, int columns, const ContactSheetOptions& options) {
  const int column = index % columns;
  const int row = index / columns;
  return {gutter + column * (options.tile_width + gutter),
          title_height + gutter + row * (options.tile_height + label_height + gutter)};
}

/// The lowest and highest y (metres) of the bodies `camera` shows in `world`, clipped to its
/// view; nothing when no body is in view.
std::optional<std::pair<float, float>> visible_extent(const World& world,
                                                      const render::Camera& camera) {
  const vec2 half(static_cast<float>(camera.width()) / (2.0f * camera.pixels_per_metre()),
                  static_cast<float>(camera.height()) / (2.0f * camera.pixels_per_metre()));
  const vec2 low = camera.center() - half;
  const vec2 high = camera.center() + half;
  std::optional<std::pair<float, float>> extent;
  for (const BodyId id : world.body_ids()) {
    const BodyView body = world.body(id);
    // A compound body's bounds cover all its shapes (kept by the world).
    const Aabb box = body.shape_count > 0 ? body.aabb : compute_aabb(*body.shape, body.transform);
    if (box.upper.x < low.x || box.lower.x > high.x || box.upper.y < low.y || box.lower.y > high.y) {
      continue;
    }
    const float bottom = std::max(box.lower.y, low.y);
    const float top = std::min(box.upper.y, high.y);
    extent = extent ? std::make_pair(std::min(extent->first, bottom), std::max(extent->second, top))
                    : std::make_pair(bottom, top);
  }
  return extent;
}

/// The sheet's camera: the scene's for a tile, moved vertically so that what it shows of the
/// bodies at the planned steps of a fresh run of the same scene is centred. A camera that
/// follows a body moves every frame anyway and is left as it is.
render::Camera centred_camera(const SceneRun& run, const FramePlan& plan,
                              const ContactSheetOptions& options) {
  const render::Camera camera = run_camera(run, options.tile_width, options.tile_height);
  if (run.scene().view.camera.mode == CameraSpec::Mode::Follow) return camera;
  SceneRun probe(run.scene(), run.params());
  std::optional<std::pair<float, float>> extent;
  for (const std::int64_t step : plan.frames) {
    while (probe.step_count() < step) probe.step();
    const auto seen = visible_extent(probe.world(), camera);
    if (!seen) continue;
    extent = extent ? std::make_pair(std::min(extent->first, seen->first),
                                     std::max(extent->second, seen->second))
                    : *seen;
  }
  if (!extent) return camera;
  return camera.with_center({camera.center().x, 0.5f * (extent->first + extent->second)});
}

}  // namespace

std::vector<OverlayName> overlay_cover(std::uint32_t flags, bool composites) {
  std::vector<const OverlayName*> candidates;
  for (const OverlayName& each : overlay_names()) {
    const bool composite = std::strcmp(each.name, "contacts") == 0 || std::strcmp(each.name, "all") == 0;
    if (composite && !composites) continue;
    if (each.flags != 0 && (flags & each.flags) == each.flags) candidates.push_back(&each);
  }
  std::stable_sort(candidates.begin(), candidates.end(), [](const OverlayName* a, const OverlayName* b) {
    return std::bitset<32>(a->flags).count() > std::bitset<32>(b->flags).count();
  });
  std::uint32_t covered = 0;
  std::vector<const OverlayName*> chosen;
  for (const OverlayName* each : candidates) {
    if ((covered | each->flags) == covered) continue;
    covered |= each->flags;
    chosen.push_back(each);
  }
  // In the order --help lists them.
  std::vector<OverlayName> cover;
  for (const OverlayName& each : overlay_names()) {
    if (std::find(chosen.begin(), chosen.end(), &each) != chosen.end()) cover.push_back(each);
  }
  return cover;
}

std::string overlay_list(std::uint32_t flags) {
  std::string text;
  for (const OverlayName& each : overlay_cover(flags, true)) {
    text += (text.empty() ? "" : ", ") + std::string(each.name);
  }
  return text.empty() ? "none" : text;  // shapes alone are no overlay
}

std::pair<int, int> contact_sheet_size(int frame_count, const ContactSheetOptions& options) {
  if (options.columns < 1) throw UsageError("--columns must be >= 1");
  const int columns = std::max(1, std::min(options.columns, frame_count));
  const int rows = (frame_count + columns - 1) / columns;
  const std::int64_t width64 =
      static_cast<std::int64_t>(columns) * (options.tile_width + gutter) + gutter;
  const std::int64_t height64 =
      title_height + static_cast<std::int64_t>(rows) * (options.tile_height + label_height + gutter) +
      gutter;
  if (width64 > limits::max_sheet_side || height64 > limits::max_sheet_side ||
      width64 * height64 > limits::max_sheet_pixels) {
    throw UsageError("sheet: " + std::to_string(frame_count) + " tiles of " +
                     std::to_string(options.tile_width) + "x" + std::to_string(options.tile_height) +
                     " in " + std::to_string(columns) + " columns make a " +
                     std::to_string(width64) + "x" + std::to_string(height64) +
                     " sheet; the limits are " + std::to_string(limits::max_sheet_side) +
                     " pixels a side and " + std::to_string(limits::max_sheet_pixels) +
                     " pixels in all (use a smaller --tile, fewer frames or other --columns)");
  }
  return {static_cast<int>(width64), static_cast<int>(height64)};
}

namespace {

/// Renders `source`'s tiles (stepping its run forward once) into `frames`, with their labels
/// (the scene's name first when `name_in_label`).
void render_tiles(const SheetSource& source, const ContactSheetOptions& options,
                  bool name_in_label, std::vector<render::Frame>& frames,
                  std::vector<std::string>& labels) {
  SceneRun& run = *source.run;
  render::FrameRenderer tiles(options.tile_width, options.tile_height);
  const render::Camera camera = centred_camera(run, source.plan, options);
  render::FrameOptions frame_options = view_frame_options(run, source.draw, options.theme);
  frame_options.show_hud = false;  // the label strip says it
  constexpr std::size_t trail_points = 240;  // 4 s of path at 60 steps per second
  render::MotionTrails trails(trail_points);
  if (!options.trails.empty()) {
    frame_options.trails = &trails;
    record_trails(options.trails, run.world(), trails);
  }
  // A tile shows the events of the steps since the tile before it.
  render::EventMarks events;
  const bool record_events = (source.draw.flags & draw_events) != 0;
  if (record_events) {
    frame_options.events = &events;
    events.start(run.world());
  }
  bool first = true;
  for (const std::int64_t step : source.plan.frames) {
    while (run.step_count() < step) {
      run.step();
      if (!options.trails.empty()) record_trails(options.trails, run.world(), trails);
      if (record_events) events.record(run.world(), run.step_count());
    }
    frame_options.show_legend = first && run.scene().view.show_legend;  // on its first tile
    first = false;
    render::HudInfo hud;
    hud.step = step;
    update_view_frame(run, frame_options, hud);
    frames.push_back(tiles.render(run.world(), frame_camera(camera, run), frame_options, hud));
    events.clear();
    labels.push_back(name_in_label ? run.scene().name + "  step " + std::to_string(step)
                                   : step_label(step, run.world().time()));
  }
}

}  // namespace

std::pair<int, int> write_contact_sheet(const std::vector<SheetSource>& sources,
                                        const ContactSheetOptions& options,
                                        const std::filesystem::path& output) {
  int count = 0;
  for (const SheetSource& source : sources) count += static_cast<int>(source.plan.frames.size());
  // Plain variables, not a structured binding: the sheet's drawing lambda captures them, which
  // C++17 allows for variables only (Clang refuses a captured binding).
  const std::pair<int, int> size = contact_sheet_size(count, options);
  const int width = size.first;
  const int height = size.second;
  const int columns = std::max(1, std::min(options.columns, count));
  const render::ThemePalette palette = render::theme_palette(options.theme);

  // Render every tile first (each simulation runs forward once), remembering its label.
  std::vector<render::Frame> frames;
  std::vector<std::string> labels;
  for (const SheetSource& source : sources) {
    render_tiles(source, options, sources.size() > 1, frames, labels);
  }
  const std::string title = sources.size() == 1
                                ? scene_title(sources.front().run->scene())
                                : std::to_string(sources.size()) + " scenes";

  // Background, title, borders and labels in one pass over the whole sheet, then the tiles
  // inside their borders.
  render::FrameRenderer sheet_renderer(width, height);
  const render::Camera sheet_camera = render::Camera::centered({0.0f, 0.0f}, 1.0f, width, height);
  render::Frame sheet;
  sheet_renderer.render_primitives(
      sheet_camera, palette.background,
      [&](render::PrimitiveRenderer& draw) {
        draw.draw_screen_rect({0.0f, 0.0f},
                              {static_cast<float>(width), static_cast<float>(title_height)},
                              palette.hud_panel);
        draw.draw_screen_text({8.0f, 6.0f}, title, palette.hud_text, text_scale);
        draw.draw_screen_text({8.0f, 30.0f}, options.caption, palette.hud_text, 1);
        for (int i = 0; i < count; ++i) {
          const auto [x, y] = tile_origin(i, columns, options);
          draw.draw_screen_rect({static_cast<float>(x - 1), static_cast<float>(y - 1)},
                                {static_cast<float>(options.tile_width + 2),
                                 static_cast<float>(options.tile_height + 2)},
                                palette.hud_text);
          draw.draw_screen_text(
              {static_cast<float>(x) + 4.0f, static_cast<float>(y + options.tile_height) + 5.0f},
              labels[static_cast<std::size_t>(i)], palette.hud_text, text_scale);
        }
      },
      sheet);
  for (int i = 0; i < count; ++i) {
    const auto [x, y] = tile_origin(i, columns, options);
    paste(frames[static_cast<std::size_t>(i)], sheet, x, y);
  }

  OutputGuard guard;
  if (!output.parent_path().empty()) {
    guard.will_create_directory(output.parent_path());
    std::filesystem::create_directories(output.parent_path());
  }
  image::save_png(output, sheet);
  guard.commit();
  return {width, height};
}

}  // namespace impulse2d::demos

/// @file frame_renderer.cpp
#include "render/frame_renderer.h"

#include "core/world.h"
#include "render/event_marks.h"
#include "render/joint_overlay.h"
#include "render/motion_trails.h"
#include "render/offscreen_context.h"
#include "render/driver_quirks.h"
#include "render/frame_scale.h"
#include "render/render_error.h"

namespace impulse2d::render {

namespace {

// `style` with its marks scaled by `scale`.
PrimitiveStyle scaled_style(PrimitiveStyle style, int scale) {
  const float s = static_cast<float>(scale);
  style.line_width *= s;
  style.arrow_head_length *= s;
  style.arrow_head_width *= s;
  style.label_scale *= scale;
  style.point_scale *= s;
  return style;
}

// The events a frame drawn with `options` shows: those recorded since the last frame, else
// the world's last step's.
std::vector<EventMark> frame_event_marks(const World& world, const FrameOptions& options, std::int64_t step) {
  if ((options.draw.flags & draw_events) == 0) return {};
  return options.events != nullptr ? options.events->marks() : last_step_event_marks(world, step);
}

}  // namespace

int frame_text_scale(const FrameOptions& options, int width, int height) {
  return options.text_scale > 0 ? options.text_scale : frame_scale(width, height);
}

HudLayout frame_hud_layout(const World& world, const Camera& camera, const FrameOptions& options,
                           const HudInfo& hud) {
  const int width = camera.width();
  const int height = camera.height();
  const float scale = static_cast<float>(frame_scale(width, height));
  HudText text;
  if (options.show_hud) text = hud_text(hud, hud_counts(world));
  std::vector<LegendEntry> entries;
  std::vector<LegendEntry> notes;
  if (options.show_legend) {
    const ThemePalette palette = theme_palette(options.theme);
    DebugDrawOptions draw_options = options.draw;
    draw_options.palette = palette.debug;
    const std::uint32_t drawn = drawn_overlay_flags(world, draw_options.flags);
    const bool trails_on = options.trails != nullptr && !options.trails->empty();
    entries = legend_entries(draw_options, drawn, trails_on, palette.trail);
    for (LegendEntry& entry : event_legend_entries(frame_event_marks(world, options, hud.step), palette.debug)) {
      entries.push_back(std::move(entry));
    }
    if (options.islands) entries.push_back({island_color(0), "island"});
    if (options.contacts.feature_ids && !world.contacts().empty()) entries.push_back({palette.debug.label, "feature id"});
    if (options.highlight) entries.push_back({highlight_color, "highlight"});
    notes = legend_notes(draw_options, drawn, camera, options.contacts.max_arrow_pixels * scale,
                         options.contacts.min_penetration_pixels * scale);
  }
  return layout_hud(width, height, text, entries, notes, frame_text_scale(options, width, height));
}

FrameRenderer::FrameRenderer(int width, int height, const PrimitiveStyle& style)
    : FrameRenderer(create_offscreen_context(width, height), style) {}

FrameRenderer::FrameRenderer(std::unique_ptr<OffscreenContext> context, const PrimitiveStyle& style)
    : context_(std::move(context)) {
  if (!context_) throw RenderError("FrameRenderer: no offscreen context given");
  context_->make_current();
  check_driver(context_->renderer());
  primitives_ = std::make_unique<PrimitiveRenderer>(
      scaled_style(style, frame_scale(context_->width(), context_->height())));
}

FrameRenderer::~FrameRenderer() {
  try {
    context_->make_current();  // GL objects are deleted under their own context
  } catch (const RenderError&) {
    return;  // no context to delete under; GL calls without one do nothing
  }
  primitives_.reset();
}

int FrameRenderer::width() const { return context_->width(); }

int FrameRenderer::height() const { return context_->height(); }

std::string FrameRenderer::fingerprint() const { return context_->renderer() + " | " + context_->version(); }

void FrameRenderer::check_camera(const Camera& camera) const {
  if (camera.width() != width() || camera.height() != height()) {
    throw RenderError("FrameRenderer: camera is " + std::to_string(camera.width()) + "x" +
                      std::to_string(camera.height()) + " but the renderer draws " +
                      std::to_string(width()) + "x" + std::to_string(height()) + " frames");
  }
}

void FrameRenderer::render(const World& world, const Camera& camera, const FrameOptions& options,
                           const HudInfo& hud, Frame& frame) {
  check_camera(camera);
  const ThemePalette palette = theme_palette(options.theme);
  DebugDrawOptions draw_options = options.draw;
  draw_options.palette = palette.debug;
  const int scale = frame_scale(width(), height());

  context_->make_current();
  primitives_->begin(camera);
  // Each group of marks is a layer over the ones before (within a layer the renderer draws
  // kind by kind). World::draw draws shapes and the body overlays; the renderer draws
  // bounding boxes, contacts and body labels itself.
  const auto draw_world = [&](std::uint32_t flags) {
    DebugDrawOptions world_options = draw_options;
    world_options.flags &= flags;
    if (world_options.flags != 0) world.draw(*primitives_, world_options);
    primitives_->next_layer();
  };
  draw_world(draw_shapes | draw_sleeping);
  // llvmpipe pays thousands of instructions per primitive, and most of a frame's primitives
  // are overlay marks a few pixels across: every layer after the shapes is rasterised on the
  // CPU, over the frame read back (docs/rendering.md, fifth pass).
  primitives_->start_software_layers();
  if (draw_options.flags & draw_aabbs) draw_bounding_boxes(*primitives_, world, palette.debug.aabb);
  primitives_->next_layer();
  draw_world(draw_broad_phase);
  draw_world(draw_velocities | draw_center_of_mass);
  if (options.islands) draw_islands(*primitives_, world);
  primitives_->next_layer();
  draw_contacts(*primitives_, world, draw_options, options.contacts, scale);
  primitives_->next_layer();
  if ((draw_options.flags & draw_joints) && world.joint_count() > 0) {
    draw_joints_overlay(*primitives_, world, draw_options, options.contacts.max_arrow_pixels * static_cast<float>(scale));
    primitives_->next_layer();
  }
  const std::vector<EventMark> events = frame_event_marks(world, options, hud.step);
  if (!events.empty()) {
    draw_event_marks(*primitives_, events, palette.debug, draw_options.velocity_scale, scale);
    primitives_->next_layer();
  }
  if (draw_options.flags & draw_body_ids) draw_body_labels(*primitives_, world, draw_options, options.body_labels);
  primitives_->next_layer();
  if (options.extra_overlays) options.extra_overlays(*primitives_, draw_options);
  primitives_->next_layer();
  if (options.highlight) draw_highlight(*primitives_, world, *options.highlight, scale);
  if (options.trails != nullptr && !options.trails->empty()) options.trails->draw(*primitives_, palette.trail);
  primitives_->next_layer();
  if (options.show_hud || options.show_legend) {
    draw_hud(*primitives_, frame_hud_layout(world, camera, options, hud), palette);
  }
  primitives_->finish(palette.background);
  context_->read_pixels(frame);
  primitives_->draw_software_layers(frame);
}

Frame FrameRenderer::render(const World& world, const Camera& camera, const FrameOptions& options,
                            const HudInfo& hud) {
  Frame frame;
  render(world, camera, options, hud, frame);
  return frame;
}

void FrameRenderer::render_primitives(const Camera& camera, Color background,
                                      const std::function<void(PrimitiveRenderer&)>& emit, Frame& frame) {
  check_camera(camera);
  context_->make_current();
  primitives_->begin(camera);
  emit(*primitives_);
  primitives_->finish(background);
  context_->read_pixels(frame);
  primitives_->draw_software_layers(frame);
}

}  // namespace impulse2d::render

#pragma once
/// @file frame_renderer.h
/// The renderer's front door: a `World` seen through a `Camera` becomes an RGBA `Frame`.
///
/// \code
///   render::FrameRenderer renderer(800, 600);
///   const render::Camera camera = render::Camera::fit(render::world_bounds(world), 800, 600);
///   render::FrameOptions options;
///   options.draw.flags = draw_all;
///   render::Frame frame;
///   renderer.render(world, camera, options, render::HudInfo{"pyramid", 0}, frame);
///   image::save_png("out/pyramid_00000.png", frame, image::PngCompression::Fast);
/// \endcode

#include "core/debug_draw.h"
#include "render/body_marks.h"
#include "render/camera.h"
#include "render/contact_overlay.h"
#include "render/frame.h"
#include "render/hud.h"
#include "render/hud_layout.h"
#include "render/island_overlay.h"
#include "render/palette.h"
#include "render/primitive_renderer.h"

#include <functional>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class OffscreenContext;
class MotionTrails;
class EventMarks;

/// How a frame looks, besides the camera.
struct FrameOptions {
  /// Overlay flags and arrow scales. Its `palette` is replaced by the theme's.
  DebugDrawOptions draw;
  Theme theme = Theme::Light;  ///< background, outlines and overlay colours
  bool show_hud = true;        ///< scene, step, simulated time and counts: one line, top-left
  /// Colour key of the overlays drawn in the frame: short entries, bottom-left (`layout_hud`).
  bool show_legend = true;
  /// Integer magnification of HUD, legend and label text (1 = 7 px capitals); 0 = the frame's
  /// `frame_scale` (1 up to 959 px on the shorter side, 6 at 4000x3000).
  int text_scale = 0;
  /// Sizes of the contact marks: maximum arrow length, normal/impulse offset, penetration bars.
  ContactOverlayStyle contacts;
  /// Names for the `draw_body_ids` overlay, by slot; empty (or an empty name) shows the slot index.
  BodyLabeler body_labels;
  /// Island colours (`draw_islands`): bodies joined by contacts share a colour.
  bool islands = false;
  /// Slot of a body to frame in `highlight_color`; nothing for none.
  std::optional<std::uint32_t> highlight;
  /// Motion trails to draw over the overlays (not owned; nullptr for none).
  const MotionTrails* trails = nullptr;
  /// The events drawn with `draw_events`: those recorded since the last frame (not owned); nullptr
  /// for the events of the world's last step alone.
  const EventMarks* events = nullptr;
  /// Extra world-space drawing after the world's own overlays and before the trails, e.g. a
  /// scene script's character overlays; empty for none. Given the frame's overlay options so
  /// it can use the theme's palette and scales.
  std::function<void(DebugDraw&, const DebugDrawOptions&)> extra_overlays;
};

/// The integer text magnification of a width x height frame drawn with `options`: its
/// `text_scale`, else the frame's `frame_scale`.
int frame_text_scale(const FrameOptions& options, int width, int height);

/// Where the HUD and legend of `world` seen through `camera` with `options` and `hud` go, and
/// what they say (`layout_hud`): what `FrameRenderer::render` draws, for tools and tests that
/// need the panels' rectangles.
HudLayout frame_hud_layout(const World& world, const Camera& camera, const FrameOptions& options,
                           const HudInfo& hud);

/// Owns an offscreen GL context and the primitive batch, and renders frames of a fixed size.
/// Use it from the thread that created it. Frames depend only on their inputs: the same
/// world, camera and options give bit-identical pixels on every run and any llvmpipe and
/// CPU rasteriser thread count (both follow `LP_NUM_THREADS`).
class FrameRenderer {
 public:
  /// A renderer with its own OSMesa context of width x height pixels. Line widths and arrow
  /// heads of `style` are multiplied by `frame_scale(width, height)`. Throws `RenderError`
  /// naming the cause on a driver it cannot run on (`check_driver`), and
  /// when the context cannot be created (naming driver and GL version) or the size is bad.
  FrameRenderer(int width, int height, const PrimitiveStyle& style = PrimitiveStyle{});
  /// A renderer drawing into `context` (any `OffscreenContext` backend), with `style` scaled
  /// as above.
  explicit FrameRenderer(std::unique_ptr<OffscreenContext> context,
                         const PrimitiveStyle& style = PrimitiveStyle{});
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  /// Frame width, pixels.
  int width() const;
  /// Frame height, pixels.
  int height() const;
  /// "GL_RENDERER | GL_VERSION" of the context, for golden-image sidecars.
  std::string fingerprint() const;

  /// Draws `world` (shapes, broad-phase pairs and body overlays via `World::draw`; bounding
  /// boxes with `draw_bounding_boxes`; islands with `draw_islands`; contacts with
  /// `draw_contacts`; events with `draw_event_marks`; body labels with `draw_body_labels`), then `extra_overlays`, the highlight,
  /// trails, HUD and legend, into `frame`, each group a layer over the ones before. Shapes are
  /// drawn by GL, every later layer on the CPU over the read-back frame
  /// (`PrimitiveRenderer::start_software_layers`). The camera must have this renderer's size
  /// (else `RenderError`).
  void render(const World& world, const Camera& camera, const FrameOptions& options,
              const HudInfo& hud, Frame& frame);
  /// As above, returning a new frame.
  Frame render(const World& world, const Camera& camera, const FrameOptions& options, const HudInfo& hud);

  /// Draws whatever `emit` sends to the batch (world primitives through its `DebugDraw`
  /// methods, or screen rectangles and text) on `background`, into `frame`, GL layers first and
  /// then any layers `emit` sends after `start_software_layers`. For tests and tools that have
  /// no world.
  void render_primitives(const Camera& camera, Color background,
                         const std::function<void(PrimitiveRenderer&)>& emit, Frame& frame);

 private:
  void check_camera(const Camera& camera) const;

  std::unique_ptr<OffscreenContext> context_;
  std::unique_ptr<PrimitiveRenderer> primitives_;
};

}  // namespace impulse2d::render

#pragma once
/// @file contact_overlay.h
/// The contact overlays as the renderer draws them (in place of `World::draw`'s plain arrows):
/// normals and impulses side by side, arrows cut at a maximum length with a break mark,
/// penetration as a bar that stays visible at resting depths, contacts of sleeping bodies
/// dimmed.

#include "core/debug_draw.h"

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;

/// Sizes of the contact marks, in screen pixels at frame scale 1 (`frame_scale.h`); each is
/// multiplied by the frame scale when drawn.
struct ContactOverlayStyle {
  /// Arrows (normals, impulses) longer than this are cut to it and get a break mark, pixels.
  float max_arrow_pixels = 120.0f;
  /// Normals start this far to one side of the contact point and normal impulses this far
  /// to the other, so the two never hide each other, pixels; farther where a penetration bar
  /// is drawn, so that neither touches it.
  float arrow_offset_pixels = 3.0f;
  /// Penetration bars shorter than this (after magnification) are drawn this long, pixels.
  float min_penetration_pixels = 8.0f;
  /// Width of a penetration bar, pixels.
  float penetration_bar_pixels = 3.0f;
  /// Opacity multiplier of the marks of a contact whose dynamic bodies all sleep or touch a
  /// sleeping body (Box2D's dimmed sleeping contacts), 0..1.
  float sleeping_opacity = 0.35f;
  /// Also write each point's feature id (hexadecimal, as `ContactPoint::feature_id`) beside it,
  /// on the side its normal points away from.
  bool feature_ids = false;
};

/// The contact flags (`draw_contact_points`, `draw_contact_normals`, `draw_normal_impulses`,
/// `draw_friction_impulses`, `draw_penetration`) that `draw_contacts` draws.
constexpr std::uint32_t contact_overlay_flags = draw_contact_points | draw_contact_normals |
                                                draw_normal_impulses | draw_friction_impulses |
                                                draw_penetration;

/// An arrow from `from` towards `to` (metres), cut to `max_pixels` on screen when longer,
/// with a break mark (two short slanted strokes across the shaft) where it was cut. Returns
/// true when it was cut.
bool draw_clamped_arrow(PrimitiveRenderer& renderer, vec2 from, vec2 to, Color color, float max_pixels);

/// Draws the contact overlays of `world` that are on in `options.flags` (with its palette and
/// scales) at integer frame scale `scale`: dots and penetration bars, then (in the next layer,
/// over them) the arrows, which stand clear of a bar where there is one, and the feature ids,
/// behind each point where no arrow goes. Dimmed: the contacts the world keeps aside between
/// sleeping bodies (or a sleeping and a static one, `World::sleeping_contacts`) and those of an
/// awake body on a sleeping one.
void draw_contacts(PrimitiveRenderer& renderer, const World& world, const DebugDrawOptions& options,
                   const ContactOverlayStyle& style, int scale);

}  // namespace impulse2d::render

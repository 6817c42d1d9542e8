#pragma once
/// @file debug_draw.h
/// What the core asks a renderer to draw. The core never knows how: render/ implements
/// `DebugDraw` with OpenGL, tests implement it with recorders.

#include "core/math.h"

#include <cstdint>
#include <string>

namespace impulse2d {

/// A colour with straight (not premultiplied) alpha, each channel in [0, 1].
struct Color {
  float r = 0.0f;  ///< red
  float g = 0.0f;  ///< green
  float b = 0.0f;  ///< blue
  float a = 1.0f;  ///< opacity
};

/// Bit flags choosing what `World::draw` emits. Each can be turned on alone.
enum DebugDrawFlag : std::uint32_t {
  draw_shapes = 1u << 0,             ///< filled shapes with outline and orientation mark
  draw_aabbs = 1u << 1,              ///< each body's bounding box
  draw_contact_points = 1u << 2,     ///< manifold points
  draw_contact_normals = 1u << 3,    ///< normal arrows at each point
  draw_normal_impulses = 1u << 4,    ///< arrows scaled by the normal impulse
  draw_friction_impulses = 1u << 5,  ///< arrows scaled by the friction impulse
  draw_penetration = 1u << 6,        ///< the overlap segment along the normal
  draw_velocities = 1u << 7,         ///< linear velocity arrows
  draw_center_of_mass = 1u << 8,     ///< a mark at each body's centre of mass
  draw_sleeping = 1u << 9,           ///< sleeping bodies dimmed
  draw_broad_phase = 1u << 10,       ///< candidate pairs from the broad phase
  draw_body_ids = 1u << 11,          ///< each body's index as a label
  /// joints: anchors, the line between them, axes, limit arcs and stops, spring coils, motor
  /// direction, reaction-force arrows
  draw_joints = 1u << 12,
  draw_all = 0x1FFFu,                ///< everything above
  /// events (events.h): touch begin (ring) and end (cross) where the pair touches, hits (a
  /// burst scaled by the approach speed), sensor begin and end at the visitor's centre.
  /// `World::draw` draws nothing for it: the renderer draws those of the steps since the last
  /// frame (render/event_marks.h). Not in `draw_all`: contact events are on by default, so it
  /// would add marks to frames drawn with `draw_all`.
  draw_events = 1u << 13,
};

/// The colours of each drawn role; a renderer sets these per theme.
struct DebugPalette {
  Color dynamic_fill{0.55f, 0.70f, 0.90f, 1.0f};    ///< awake dynamic bodies
  Color kinematic_fill{0.60f, 0.85f, 0.60f, 1.0f};  ///< kinematic bodies
  Color static_fill{0.65f, 0.65f, 0.65f, 1.0f};     ///< static bodies
  Color sleeping_fill{0.75f, 0.78f, 0.82f, 1.0f};   ///< sleeping bodies (dimmed)
  Color outline{0.10f, 0.10f, 0.15f, 1.0f};         ///< shape outlines and orientation marks
  Color aabb{0.80f, 0.40f, 0.80f, 1.0f};            ///< bounding boxes
  Color contact_point{0.90f, 0.10f, 0.10f, 1.0f};   ///< contact points
  Color contact_normal{0.00f, 0.45f, 0.70f, 1.0f};  ///< normal arrows
  Color normal_impulse{0.84f, 0.37f, 0.00f, 1.0f};  ///< normal impulse arrows
  Color friction_impulse{0.00f, 0.62f, 0.45f, 1.0f};///< friction impulse arrows
  Color penetration{0.80f, 0.47f, 0.65f, 1.0f};     ///< overlap segments
  Color velocity{0.34f, 0.71f, 0.91f, 1.0f};        ///< velocity arrows
  Color center_of_mass{0.0f, 0.0f, 0.0f, 1.0f};     ///< centre of mass marks
  Color broad_phase_pair{0.90f, 0.60f, 0.00f, 0.6f};///< lines between candidate pair centres
  Color label{0.0f, 0.0f, 0.0f, 1.0f};              ///< text
  Color joint{0.47f, 0.24f, 0.63f, 1.0f};           ///< joint anchors, lines, axes, limits, springs, motors
  Color joint_reaction{0.80f, 0.12f, 0.35f, 1.0f};  ///< joint reaction-force arrows
  Color sensor_fill{0.94f, 0.89f, 0.26f, 0.35f};    ///< sensor bodies (see-through)
  Color event_touch{0.00f, 0.47f, 0.47f, 1.0f};     ///< touch begin rings and end crosses
  Color event_hit{0.75f, 0.00f, 0.00f, 1.0f};       ///< hit bursts
  Color event_sensor{0.63f, 0.51f, 0.00f, 1.0f};    ///< sensor begin rings and end crosses
};

/// Options of one `World::draw` call.
struct DebugDrawOptions {
  std::uint32_t flags = draw_shapes;  ///< which `DebugDrawFlag`s are on
  DebugPalette palette;               ///< colours of each role
  float impulse_scale = 1.0f;         ///< metres of arrow per N s of impulse
  float velocity_scale = 0.1f;        ///< metres of arrow per m/s
  float normal_length = 0.3f;         ///< metres, length of normal arrows
  float penetration_scale = 1.0f;     ///< magnifies overlap segments (1 = true length)
  /// Interpolation between the previous and current step for drawing, in [0, 1]:
  /// drawn = previous * (1 - alpha) + current * alpha.
  float interpolation_alpha = 1.0f;
};

/// Receives drawing commands in world coordinates (metres, y up). Implement every method.
class DebugDraw {
 public:
  virtual ~DebugDraw() = default;
  /// A filled convex polygon with an outline.
  virtual void draw_solid_polygon(const vec2* vertices, int count, Color fill, Color outline) = 0;
  /// A filled circle with an outline and a radius line from the centre along `axis` (unit).
  virtual void draw_solid_circle(vec2 center, float radius, vec2 axis, Color fill, Color outline) = 0;
  /// A line segment of constant screen width.
  virtual void draw_segment(vec2 from, vec2 to, Color color) = 0;
  /// An arrow from `from` to `to` with a head at `to`.
  virtual void draw_arrow(vec2 from, vec2 to, Color color) = 0;
  /// A dot of `size_pixels` diameter on screen.
  virtual void draw_point(vec2 position, float size_pixels, Color color) = 0;
  /// A text label anchored at its lower-left corner.
  virtual void draw_text(vec2 position, const std::string& text, Color color) = 0;
};

}  // namespace impulse2d

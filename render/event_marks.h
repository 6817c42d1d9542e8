#pragma once
/// @file event_marks.h
/// The events overlay (`draw_events`): where the world's events (events.h) happened, kept step
/// by step between two frames and drawn as marks. A touch begins with a ring and ends with a
/// cross where the pair touches, a hit is a burst whose rays grow with its approach speed, and
/// a sensor's begin (ring) and end (cross) sit at the visitor's centre in the sensor colour.
/// A touch that ends because one of its bodies was removed is crossed where the pair last
/// touched (`EventMarks` remembers it from the step before).

#include "core/body.h"
#include "core/debug_draw.h"
#include "render/hud.h"

#include <cstdint>
#include <vector>

namespace impulse2d {
class World;
}

namespace impulse2d::render {

class PrimitiveRenderer;

/// What an event mark stands for.
enum class EventKind : std::uint8_t {
  touch_begin,   ///< two shapes began touching (ring)
  touch_end,     ///< two shapes stopped touching (cross)
  hit,           ///< an impact faster than the world's hit threshold (burst)
  sensor_begin,  ///< a shape entered a sensor (ring, sensor colour)
  sensor_end,    ///< a shape left a sensor (cross, sensor colour)
};

/// One event where the overlay draws it.
struct EventMark {
  EventKind kind = EventKind::touch_begin;  ///< what happened
  /// Where, metres: the mean of the pair's contact points (the closest points between the two
  /// shapes when the contact is gone; for an end whose body was removed, the mean of the
  /// pair's contact points after the step before), a hit's point, a sensor visitor's centre.
  vec2 point{0.0f, 0.0f};
  float speed = 0.0f;     ///< a hit's approach speed, m/s (0 for the other kinds)
  std::int64_t step = 0;  ///< the step it happened in
};

/// Number of marks of each kind.
struct EventCounts {
  int touch_begin = 0;   ///< rings of touches
  int touch_end = 0;     ///< crosses of touches
  int hit = 0;           ///< bursts
  int sensor_begin = 0;  ///< rings of sensors
  int sensor_end = 0;    ///< crosses of sensors
  /// All of them.
  int total() const { return touch_begin + touch_end + hit + sensor_begin + sensor_end; }
};

/// The marks of the events of `world`'s last step, labelled `step`, in the world's order
/// (touch begins, ends, hits, sensor begins, ends). An end whose body was removed has no place
/// left in the world and is left out (`EventMarks::record` places it).
std::vector<EventMark> last_step_event_marks(const World& world, std::int64_t step);

/// The marks of the steps since the last frame: `start` before the first step, `record` after
/// each step, draw, `clear` after each frame, so that frames taken every N steps lose no event.
class EventMarks {
 public:
  /// Remembers where `world`'s pairs touch now (as `record` does after each step), so that a
  /// touch whose body is removed before the next step is still crossed where it was.
  void start(const World& world);
  /// Appends the marks of `world`'s last step (`last_step_event_marks`), labelled `step`, with
  /// the ends of pairs whose body was removed placed where the pair touched when `start` or the
  /// previous `record` saw it; then remembers where the pairs touch now.
  void record(const World& world, std::int64_t step);
  /// Forgets every mark (after a frame is drawn); the touch points are kept.
  void clear() { marks_.clear(); }
  /// The marks recorded since the last `clear`, in step order.
  const std::vector<EventMark>& marks() const { return marks_; }

 private:
  // Where a pair of bodies touched when last seen: the mean of its contact points.
  struct TouchPoint {
    BodyId body_a;
    BodyId body_b;
    vec2 point;
  };
  void remember_touches(const World& world);
  std::vector<EventMark> marks_;
  std::vector<TouchPoint> touches_;  // the world's contacts with points, in its order
};

/// How many marks of each kind `marks` holds.
EventCounts count_event_marks(const std::vector<EventMark>& marks);

/// Sizes of the marks in screen pixels at frame scale 1 (multiplied by the frame scale).
struct EventMarkStyle {
  float ring_radius_pixels = 5.0f;   ///< begin rings
  float cross_half_pixels = 4.0f;    ///< half the width of an end cross
  /// A burst's rays are the approach speed on the velocity arrows' scale
  /// (`DebugDrawOptions::velocity_scale` metres per m/s), at least this long...
  float burst_min_pixels = 5.0f;
  float burst_max_pixels = 30.0f;    ///< ... and at most this long
  float burst_inner_pixels = 3.0f;   ///< gap between the point and the rays
};

/// Draws `marks` in `palette`'s event colours at integer frame scale `scale`, bursts sized by
/// `velocity_scale` (metres per m/s).
void draw_event_marks(PrimitiveRenderer& renderer, const std::vector<EventMark>& marks, const DebugPalette& palette,
                      float velocity_scale, int scale, const EventMarkStyle& style = EventMarkStyle{});

/// The legend's entries for `marks`: "touch o/x" (ring begin, cross end), "hit", "sensor o/x",
/// each only when some mark of it is drawn.
std::vector<LegendEntry> event_legend_entries(const std::vector<EventMark>& marks, const DebugPalette& palette);

}  // namespace impulse2d::render

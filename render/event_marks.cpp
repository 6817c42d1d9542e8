/// @file event_marks.cpp
#include "render/event_marks.h"

#include "core/query.h"
#include "core/world.h"
#include "render/primitive_renderer.h"

#include <algorithm>
#include <utility>

namespace impulse2d::render {
namespace {

constexpr float kTwoPi = 6.28318530718f;
constexpr int kRingSegments = 12;
constexpr int kBurstRays = 8;

// The mean of a contact's points; false for a contact without points.
bool contact_point(const Contact& contact, vec2& point) {
  if (contact.point_count == 0) return false;
  vec2 sum(0.0f, 0.0f);
  for (int i = 0; i < contact.point_count; ++i) sum += contact.points[i].point;
  point = sum / static_cast<float>(contact.point_count);
  return true;
}

// Shape `index` of `body` and where it lies in the world (a compound body's shape is placed by
// its local transform).
std::pair<const Shape*, Transform> placed_shape(const BodyView& body, std::uint32_t index) {
  if (body.shape_count == 0 || index >= static_cast<std::uint32_t>(body.shape_count)) {
    return {body.shape, body.transform};
  }
  return {&body.shapes[index].shape, compose(body.transform, body.shapes[index].local)};
}

// Where shapes a and b touch: the mean of their contact's points, awake or asleep; without a
// contact, midway between the closest points of the two shapes. Nothing when a body is gone.
bool touch_point(const World& world, ShapeId a, ShapeId b, vec2& point) {
  for (const std::vector<Contact>* contacts : {&world.contacts(), &world.sleeping_contacts()}) {
    for (const Contact& contact : *contacts) {
      if (contact.body_a == a.body && contact.body_b == b.body && contact.child_a == a.index &&
          contact.child_b == b.index && contact_point(contact, point)) {
        return true;
      }
    }
  }
  if (!world.is_valid(a.body) || !world.is_valid(b.body)) return false;
  const BodyView body_a = world.body(a.body);
  const BodyView body_b = world.body(b.body);
  const auto [shape_a, at_a] = placed_shape(body_a, a.index);
  const auto [shape_b, at_b] = placed_shape(body_b, b.index);
  const ShapeDistance distance = shape_distance(*shape_a, at_a, *shape_b, at_b);
  point = distance.distance > 0.0f ? 0.5f * (distance.point_a + distance.point_b)
                                   : 0.5f * (body_a.transform.position + body_b.transform.position);
  return true;
}

void draw_ring(PrimitiveRenderer& renderer, vec2 center, float radius, Color color) {
  vec2 previous = center + vec2(radius, 0.0f);
  for (int i = 1; i <= kRingSegments; ++i) {
    const Rotation turn = Rotation::from_angle(kTwoPi * static_cast<float>(i) / kRingSegments);
    const vec2 next = center + turn.rotate(vec2(radius, 0.0f));
    renderer.draw_segment(previous, next, color);
    previous = next;
  }
}

void draw_cross(PrimitiveRenderer& renderer, vec2 center, float half, Color color) {
  renderer.draw_segment(center + vec2(-half, -half), center + vec2(half, half), color);
  renderer.draw_segment(center + vec2(-half, half), center + vec2(half, -half), color);
}

void draw_burst(PrimitiveRenderer& renderer, vec2 center, float inner, float length, Color color) {
  for (int i = 0; i < kBurstRays; ++i) {
    const Rotation turn = Rotation::from_angle(kTwoPi * (static_cast<float>(i) + 0.5f) / kBurstRays);
    renderer.draw_segment(center + turn.rotate(vec2(inner, 0.0f)), center + turn.rotate(vec2(inner + length, 0.0f)),
                          color);
  }
}

}  // namespace

std::vector<EventMark> last_step_event_marks(const World& world, std::int64_t step) {
  std::vector<EventMark> marks;
  const ContactEvents& contact = world.contact_events();
  const SensorEvents& sensor = world.sensor_events();
  vec2 point;
  for (const ContactBeginTouchEvent& event : contact.begin) {
    if (touch_point(world, event.shape_a, event.shape_b, point)) marks.push_back({EventKind::touch_begin, point, 0.0f, step});
  }
  for (const ContactEndTouchEvent& event : contact.end) {
    if (touch_point(world, event.shape_a, event.shape_b, point)) marks.push_back({EventKind::touch_end, point, 0.0f, step});
  }
  for (const ContactHitEvent& event : contact.hit) {
    marks.push_back({EventKind::hit, event.point, event.approach_speed, step});
  }
  for (const SensorBeginTouchEvent& event : sensor.begin) {
    if (world.is_valid(event.visitor_body)) {
      marks.push_back({EventKind::sensor_begin, world.body(event.visitor_body).transform.position, 0.0f, step});
    }
  }
  for (const SensorEndTouchEvent& event : sensor.end) {
    if (world.is_valid(event.visitor_body)) {
      marks.push_back({EventKind::sensor_end, world.body(event.visitor_body).transform.position, 0.0f, step});
    }
  }
  return marks;
}

void EventMarks::start(const World& world) { remember_touches(world); }

void EventMarks::record(const World& world, std::int64_t step) {
  const std::vector<EventMark> last = last_step_event_marks(world, step);
  // The ends left out there (a body removed) come first among the ends, in the world's order.
  std::size_t at = 0;
  while (at < last.size() && last[at].kind == EventKind::touch_begin) ++at;
  marks_.insert(marks_.end(), last.begin(), last.begin() + static_cast<std::ptrdiff_t>(at));
  for (const ContactEndTouchEvent& event : world.contact_events().end) {
    if (world.is_valid(event.body_a) && world.is_valid(event.body_b)) continue;
    for (const TouchPoint& touch : touches_) {
      if (touch.body_a == event.body_a && touch.body_b == event.body_b) {
        marks_.push_back({EventKind::touch_end, touch.point, 0.0f, step});
        break;
      }
    }
  }
  marks_.insert(marks_.end(), last.begin() + static_cast<std::ptrdiff_t>(at), last.end());
  remember_touches(world);
}

void EventMarks::remember_touches(const World& world) {
  touches_.clear();
  for (const std::vector<Contact>* contacts : {&world.contacts(), &world.sleeping_contacts()}) {
    for (const Contact& contact : *contacts) {
      vec2 point;
      if (contact_point(contact, point)) touches_.push_back({contact.body_a, contact.body_b, point});
    }
  }
}

EventCounts count_event_marks(const std::vector<EventMark>& marks) {
  EventCounts counts;
  for (const EventMark& mark : marks) {
    switch (mark.kind) {
      case EventKind::touch_begin: ++counts.touch_begin; break;
      case EventKind::touch_end: ++counts.touch_end; break;
      case EventKind::hit: ++counts.hit; break;
      case EventKind::sensor_begin: ++counts.sensor_begin; break;
      case EventKind::sensor_end: ++counts.sensor_end; break;
    }
  }
  return counts;
}

void draw_event_marks(PrimitiveRenderer& renderer, const std::vector<EventMark>& marks, const DebugPalette& palette,
                      float velocity_scale, int scale, const EventMarkStyle& style) {
  const float pixels_per_metre = renderer.camera().pixels_per_metre();
  const float metres = static_cast<float>(scale) / pixels_per_metre;  // per pixel at frame scale 1
  for (const EventMark& mark : marks) {
    switch (mark.kind) {
      case EventKind::touch_begin:
        draw_ring(renderer, mark.point, style.ring_radius_pixels * metres, palette.event_touch);
        break;
      case EventKind::touch_end:
        draw_cross(renderer, mark.point, style.cross_half_pixels * metres, palette.event_touch);
        break;
      case EventKind::hit: {
        const float pixels = mark.speed * velocity_scale * pixels_per_metre / static_cast<float>(scale);
        const float length = std::clamp(pixels, style.burst_min_pixels, style.burst_max_pixels) * metres;
        draw_burst(renderer, mark.point, style.burst_inner_pixels * metres, length, palette.event_hit);
        break;
      }
      case EventKind::sensor_begin:
        draw_ring(renderer, mark.point, style.ring_radius_pixels * metres, palette.event_sensor);
        break;
      case EventKind::sensor_end:
        draw_cross(renderer, mark.point, style.cross_half_pixels * metres, palette.event_sensor);
        break;
    }
  }
}

std::vector<LegendEntry> event_legend_entries(const std::vector<EventMark>& marks, const DebugPalette& palette) {
  const EventCounts counts = count_event_marks(marks);
  std::vector<LegendEntry> entries;
  if (counts.touch_begin + counts.touch_end > 0) entries.push_back({palette.event_touch, "touch o/x"});
  if (counts.hit > 0) entries.push_back({palette.event_hit, "hit"});
  if (counts.sensor_begin + counts.sensor_end > 0) entries.push_back({palette.event_sensor, "sensor o/x"});
  return entries;
}

}  // namespace impulse2d::render

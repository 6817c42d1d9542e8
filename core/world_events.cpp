// Events of a step (events.h): after the step, this step's touching pairs and sensor overlaps
// are compared with the last step's (both sorted by slot pair), so the solver never calls out
// and a world without events steps exactly as before (events only read what the step made; the
// one thing the step does for them is judge each awake contact's touch as prepare passes it).
#include "core/world_events.h"

#include "core/collide.h"
#include "core/solver/contact_touch.h"
#include "core/solver/prefetch.h"
#include "core/solver/world_state.h"
#include "core/solver/worker_pool.h"

#include <algorithm>

namespace impulse2d {

namespace {

ShapeId shape_a_of(const EventPair& pair) { return ShapeId{pair.a, pair.shape_a}; }
ShapeId shape_b_of(const EventPair& pair) { return ShapeId{pair.b, pair.shape_b}; }

EventPair pair_of(const Contact& contact) {
  return EventPair{contact.body_a, contact.body_b, contact.child_a, contact.child_b};
}

bool key_less(const EventPair& a, const EventPair& b) { return a.key() < b.key(); }

FreeVelocities free_velocities(const WorldEvents& events) {
  return FreeVelocities{events.free_linear_velocity.data(), events.free_angular_velocity.data()};
}

// True when begin/end events of contacts are collected after this step.
bool collects_contact_events(const WorldEvents& events) {
  return events.contact_event_bodies > 0 || !events.touching.empty();
}

template <class Vector>
void reserve_at_least(Vector& vector, std::size_t size) {
  if (vector.capacity() < size) vector.reserve(size);
}

// Calls begin(pair) for each pair of `now` not in `before` and end(pair) for each of `before`
// not in `now`; both sorted by key; the calls come in key order.
template <class Begin, class End>
void compare_pairs(const std::vector<EventPair>& before, const std::vector<EventPair>& now,
                   Begin begin, End end) {
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < before.size() || j < now.size()) {
    if (j == now.size() || (i < before.size() && before[i].key() < now[j].key())) {
      end(before[i++]);
    } else if (i == before.size() || now[j].key() < before[i].key()) {
      begin(now[j++]);
    } else {
      ++i;
      ++j;
    }
  }
}

// True when this step's touches are last step's (see `WorldEvents::touching_is_current`): every
// contact touching now is a contact whose flag said so before the step and did not change, so
// the pairs touching now are among last step's, and as many of them means all of them.
bool touches_unchanged(const WorldState& world, bool all_want) {
  const WorldEvents& events = world.events;
  const WideContactSolver::TouchTally& tally = world.wide_contacts.touch_tally();
  return events.touching_is_current && !events.always_walk && tally.valid && !tally.changed &&
         all_want && world.sleeping_contacts.empty() && tally.touching == events.touching.size();
}

void collect_contact_events(WorldState& world) {
  WorldEvents& events = world.events;
  // When every body asks for contact events (the default) no body need be read.
  const bool all_want = events.contact_event_bodies == world.living_body_count;
  if (touches_unchanged(world, all_want)) {
    ++events.walks_skipped;
    return;  // nothing began or ended: `touching` stays as it is
  }
  const float slop = world.settings.slop;
  const float dt = world.settings.time_step;
  std::vector<EventPair>& next = events.next;
  reserve_at_least(next, world.contacts.capacity() + world.sleeping_contacts.capacity());
  next.clear();
  reserve_at_least(events.contact.begin, next.capacity());
  reserve_at_least(events.contact.end, events.touching.capacity() + events.contact.end.size());
  auto wants = [&world, all_want](const Contact& contact) {
    return all_want || world.bodies[contact.body_a.index].enable_contact_events ||
           world.bodies[contact.body_b.index].enable_contact_events;
  };
  // This step's touching pairs come in key order, as last step's are kept: one walk over both
  // finds the pairs that began (not touching before) and ended (touching before, not now).
  const std::vector<EventPair>& before = events.touching;
  std::size_t next_before = 0;  // last step's pairs below it have been matched or ended
  auto end_before = [&events, &before, &next_before]() {
    const EventPair& pair = before[next_before++];
    events.contact.end.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
  };
  auto touches_now = [&](const EventPair& pair) {
    while (next_before < before.size() && before[next_before].key() < pair.key()) end_before();
    if (next_before < before.size() && before[next_before].key() == pair.key()) {
      ++next_before;  // still touching
    } else {
      events.contact.begin.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
    }
    next.push_back(pair);
  };
  // Merge the awake and the set-aside contacts (each sorted by pair, disjoint): a pair that
  // fell asleep keeps touching. An awake contact's touch was judged by prepare this step (its
  // first cache line holds all this reads); a set-aside one is judged here.
  const FreeVelocities velocities = free_velocities(events);
  const std::vector<Contact>& awake = world.contacts;
  const std::vector<Contact>& resting = world.sleeping_contacts;
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < awake.size() || j < resting.size()) {
    const bool take_awake =
        j == resting.size() ||
        (i < awake.size() && pair_of(awake[i]).key() < pair_of(resting[j]).key());
    // The walk reads one cache line of each contact, far apart: ask for the lines ahead.
    if (i + prefetch_items_ahead < awake.size()) {
      prefetch_bytes(awake[i + prefetch_items_ahead], 0, 64);
    }
    const Contact& contact = take_awake ? awake[i++] : resting[j++];
    const bool touching = take_awake ? contact.enabled && contact.touching
                                     : touches_in_step(velocities, contact, slop, dt);
    if (touching && wants(contact)) touches_now(pair_of(contact));
  }
  while (next_before < before.size()) end_before();
  std::swap(events.touching, next);
  // The flags of the awake contacts made `touching` (the walk read each); with contacts set
  // aside (judged here, not by prepare) or bodies that do not ask, the next step walks again.
  const WideContactSolver::TouchTally& tally = world.wide_contacts.touch_tally();
  events.touching_is_current = tally.valid && all_want && resting.empty();
}

// A hit is an impact: a point approaching faster than the threshold that the step must stop,
// because moving freely from its gap it would end the step inside the other body (the solver
// pushes at it: Box2D v3 asks for a normal impulse at the point). A point that only closes its
// gap within the step (the speculative contact lets it arrive at the surface) is hit in the
// next step, when it is stopped, not twice; and a corner still in the air while another point
// of the pair rests is not hit until it lands.
void collect_hit_events(WorldState& world) {
  WorldEvents& events = world.events;
  const float dt = world.settings.time_step;
  reserve_at_least(events.contact.hit, world.contacts.capacity());
  const FreeVelocities velocities = free_velocities(events);
  for (const Contact& contact : world.contacts) {
    const Body& a = world.bodies[contact.body_a.index];
    const Body& b = world.bodies[contact.body_b.index];
    if (!(a.enable_hit_events || b.enable_hit_events) || !contact.enabled) continue;
    int fastest = -1;
    float fastest_speed = events.hit_event_threshold;
    for (int p = 0; p < contact.point_count; ++p) {
      const float approach = free_approach_speed(velocities, contact, contact.points[p]);
      const float gap = -contact.points[p].depth;
      if (approach > fastest_speed && gap - approach * dt < 0.0f) {
        fastest_speed = approach;
        fastest = p;
      }
    }
    if (fastest < 0) continue;
    events.contact.hit.push_back({shape_a_of(pair_of(contact)), shape_b_of(pair_of(contact)), contact.body_a,
                                  contact.body_b, contact.points[fastest].point, contact.normal,
                                  fastest_speed});
  }
}

void collect_sensor_events(WorldState& world) {
  WorldEvents& events = world.events;
  std::vector<EventPair>& next = events.next;
  next.clear();
  for (std::uint32_t s = 0; s < world.bodies.size(); ++s) {
    const Body& sensor = world.bodies[s];
    if (!world.alive[s] || !(sensor.is_sensor || sensor.has_sensor_shapes)) continue;
    world.broad_phase.query(sensor.aabb, events.nearby);  // ascending slots
    for (const std::uint32_t o : events.nearby) {
      const Body& other = world.bodies[o];
      if (o == s || !world.alive[o] || other.is_sensor || !other.enable_sensor_events) continue;
      if (other.type == BodyType::Static && !sensor.sensor_detects_static) continue;
      if ((other.collision_layers & sensor.collision_layers) == 0) continue;
      if (!other.aabb.overlaps(sensor.aabb)) continue;
      // Each pair of shapes (one pair unless a body is compound) whose layers meet and that
      // overlap, in (sensor's shape, other's shape) order. A sensor body's shapes all sense; a
      // compound body's sensor shapes sense, and its other shapes are seen like any body's.
      for (int i = 0; i < shape_count_of(sensor); ++i) {
        if (!sensor.is_sensor && !is_sensor_shape(sensor, i)) continue;
        const Transform sensor_at = shape_transform(sensor, i);
        for (int k = 0; k < shape_count_of(other); ++k) {
          if ((layers_of(sensor, i) & layers_of(other, k)) == 0 || is_sensor_shape(other, k)) continue;
          if (collide(shape_of(sensor, i), sensor_at, shape_of(other, k), shape_transform(other, k))
                  .point_count == 0) {
            continue;
          }
          next.push_back({sensor.id, other.id, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(k)});
        }
      }
    }
  }
  reserve_at_least(events.sensor.begin, next.capacity());
  reserve_at_least(events.sensor.end, events.sensor_overlaps.capacity() + events.sensor.end.size());
  compare_pairs(
      events.sensor_overlaps, next,
      [&events](const EventPair& pair) {
        events.sensor.begin.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
      },
      [&events](const EventPair& pair) {
        events.sensor.end.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
      });
  std::swap(events.sensor_overlaps, next);
}

}  // namespace

void begin_step_events(WorldState& world, WorkerPool* pool) {
  WorldEvents& events = world.events;
  events.contact.begin.clear();
  events.contact.end.clear();
  events.contact.hit.clear();
  events.sensor.begin.clear();
  events.sensor.end.clear();
  if (!events.removed_touches.empty()) {
    std::stable_sort(events.removed_touches.begin(), events.removed_touches.end(), key_less);
    for (const EventPair& pair : events.removed_touches) {
      events.contact.end.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
    }
    events.removed_touches.clear();
  }
  if (!events.removed_overlaps.empty()) {
    std::stable_sort(events.removed_overlaps.begin(), events.removed_overlaps.end(), key_less);
    for (const EventPair& pair : events.removed_overlaps) {
      events.sensor.end.push_back({shape_a_of(pair), shape_b_of(pair), pair.a, pair.b});
    }
    events.removed_overlaps.clear();
  }
  if (events.hit_event_bodies == 0 && events.contact_event_bodies == 0 && events.touching.empty()) return;
  // The velocity each body would end the step with if nothing touched it: what it carries
  // into the step plus the step's gravity and applied forces (a pass over the bodies, read
  // only; contact events and hits are judged on it).
  const std::size_t count = world.bodies.size();
  if (events.free_linear_velocity.size() < count) {
    events.free_linear_velocity.resize(count);
    events.free_angular_velocity.resize(count);
  }
  const float dt = world.settings.time_step;
  parallel_for(pool, count, 512, [&world, &events, dt](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Body& body = world.bodies[i];
      vec2 linear = body.linear_velocity;
      float angular = body.angular_velocity;
      if (world.alive[i] && body.type == BodyType::Dynamic && body.awake) {
        linear += (world.settings.gravity * body.gravity_scale + body.force * body.inverse_mass) * dt;
        angular += body.inverse_inertia * body.torque * dt;
      }
      events.free_linear_velocity[i] = linear;
      events.free_angular_velocity[i] = angular;
    }
  });
}

FreeVelocities touch_velocities(const WorldEvents& events) {
  return collects_contact_events(events) ? free_velocities(events) : FreeVelocities{};
}

void collect_step_events(WorldState& world) {
  WorldEvents& events = world.events;
  if (collects_contact_events(events)) {
    collect_contact_events(world);
  } else {
    events.touching_is_current = false;  // the flags are not judged while no one asks
  }
  if (events.hit_event_bodies > 0) collect_hit_events(world);
  if (events.sensor_bodies > 0 || !events.sensor_overlaps.empty()) collect_sensor_events(world);
}

void end_events_of_removed_body(WorldState& world, BodyId id) {
  WorldEvents& events = world.events;
  auto move_out = [&id](std::vector<EventPair>& from, std::vector<EventPair>& into) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < from.size(); ++i) {
      if (from[i].a == id || from[i].b == id) {
        into.push_back(from[i]);
      } else {
        from[kept++] = from[i];
      }
    }
    from.resize(kept);
  };
  move_out(events.touching, events.removed_touches);
  move_out(events.sensor_overlaps, events.removed_overlaps);
}

}  // namespace impulse2d

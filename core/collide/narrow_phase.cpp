#include "core/collide/narrow_phase.h"

#include "core/collide.h"
#include "core/solver/contact_friction_state.h"
#include "core/solver/contact_recycle.h"
#include "core/collide/speculative_meeting.h"

#include <algorithm>
#include <cmath>

namespace impulse2d {

namespace {

// Gap (metres) beyond which a pair counts as apart again for a kept contact decision.
constexpr float separated_gap = 1.0e-3f;

// The largest depth (metres) of a manifold's points.
float deepest_depth(const Manifold& manifold) {
  float deepest = manifold.points[0].depth;
  for (int i = 1; i < manifold.point_count; ++i) deepest = std::max(deepest, manifold.points[i].depth);
  return deepest;
}

// Relative tangential speed (m/s) of B against A at the contact's first point.
float tangential_speed(const Body& a, const Body& b, const Contact& contact) {
  const vec2 point = contact.points[0].point;
  const vec2 velocity_b = b.linear_velocity + cross(b.angular_velocity, point - b.transform.position);
  const vec2 velocity_a = a.linear_velocity + cross(a.angular_velocity, point - a.transform.position);
  return glm::dot(velocity_b - velocity_a, right_perpendicular(contact.normal));
}

// The contact's coefficients from its shapes' materials (its bodies', unless compound) by the
// world's mixing rules.
void mix_materials(const Body& a, const Body& b, const WorldSettings& settings, Contact& contact) {
  const Material& material_a = material_of(a, contact.child_a);
  const Material& material_b = material_of(b, contact.child_b);
  contact.static_friction = mix_friction(material_a.static_friction, material_b.static_friction,
                                         settings.friction_mixing);
  contact.dynamic_friction = mix_friction(material_a.dynamic_friction,
                                          material_b.dynamic_friction, settings.friction_mixing);
  // Mixing can put dynamic above static (e.g. root-sum-squares never does, but a custom
  // rule might); Coulomb's model needs static >= dynamic.
  if (contact.dynamic_friction > contact.static_friction) {
    contact.dynamic_friction = contact.static_friction;
  }
  contact.restitution =
      mix_restitution(material_a.restitution, material_b.restitution, settings.restitution_mixing);
}

// A kept point that bounced or was caught last step drops its impulses: a collision's impulse
// is not a load to warm-start (see ContactPoint::bounced, ContactPoint::caught).
void forget_bounced_impulses(Contact& contact) {
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    if (!point.bounced && !point.caught) continue;
    point.normal_impulse = 0.0f;
    point.tangent_impulse = 0.0f;
    point.bounced = false;
    point.caught = false;
  }
}

// Copies last step's impulses into points whose feature ids match.
void carry_over_impulses(const Contact& old_contact, Contact& contact) {
  for (int i = 0; i < contact.point_count; ++i) {
    ContactPoint& point = contact.points[i];
    for (int k = 0; k < old_contact.point_count; ++k) {
      const ContactPoint& old_point = old_contact.points[k];
      if (old_point.feature_id == point.feature_id) {
        // A collision's impulse is not a load to warm-start (see ContactPoint::bounced).
        if (old_point.bounced || old_point.caught) break;
        point.normal_impulse = old_point.normal_impulse;
        point.tangent_impulse = old_point.tangent_impulse;
        break;
      }
    }
  }
}

// True when the speculative contact would push bodies that pass each other within `dt`.
bool is_ghost(const Body& a, const Body& b, const Contact& contact, const WorldSettings& settings,
              float dt) {
  // A touching point makes it a real contact: most contacts stop here, before any prediction.
  for (int i = 0; i < contact.point_count; ++i) {
    if (contact.points[i].depth >= 0.0f) return false;
  }
  return is_ghost_contact(a, predict_motion(a, settings, dt), b, predict_motion(b, settings, dt),
                          contact, dt);
}

}  // namespace

namespace {

// Pairs a worker takes at least at a time.
constexpr std::size_t min_pairs_per_chunk = 32;

// The speculative margin (metres) pair (a, b) is collided with.
float pair_margin(const Body& a, const Body& b, const std::vector<float>& reach,
                  const WorldSettings& settings, const BodyPair& pair) {
  return settings.speculative_margin > 0.0f && a.speculative && b.speculative
             ? settings.speculative_margin + reach[pair.first] + reach[pair.second]
             : 0.0f;
}

// Fills `jobs` (one per pair) on `pool`'s workers: for each pair of single-shape bodies,
// whether last step's contact of the pair (`contacts`, sorted by pair, still unchanged) may be
// recycled, else its fresh manifold. The matching of pairs to old contacts is one merge walk
// here; the rest is per pair.
void run_pair_jobs(const std::vector<Body>& bodies, const std::vector<BodyPair>& pairs,
                   const std::vector<float>& reach, const WorldSettings& settings, float dt,
                   std::vector<Contact>& contacts, WorkerPool* pool,
                   std::vector<NarrowPhaseJob>& jobs) {
  jobs.resize(pairs.size());
  parallel_for(pool, pairs.size(), min_pairs_per_chunk, [&](std::size_t begin, std::size_t end) {
    // Each chunk finds its first pair's place among the old contacts by bisection, then walks.
    const auto precedes = [](const Contact& old, const BodyPair& pair) {
      if (old.body_a.index != pair.first) return old.body_a.index < pair.first;
      return old.body_b.index < pair.second;  // (0, 0) comes first among a pair's children
    };
    std::size_t read = static_cast<std::size_t>(
        std::lower_bound(contacts.begin(), contacts.end(), pairs[begin], precedes) - contacts.begin());
    for (std::size_t i = begin; i < end; ++i) {
      const BodyPair& pair = pairs[i];
      const Body& a = bodies[pair.first];
      const Body& b = bodies[pair.second];
      NarrowPhaseJob& job = jobs[i];
      job.compound = a.compound || b.compound;
      job.recycle = false;
      job.ghost = false;
      if (job.compound) continue;
      while (read < contacts.size() && precedes(contacts[read], pair)) ++read;
      // A single-shape pair's contact has children (0, 0): the first of the pair's contacts.
      const bool touched_before = read < contacts.size() && contacts[read].body_a == a.id &&
                                  contacts[read].body_b == b.id && contacts[read].child_a == 0 &&
                                  contacts[read].child_b == 0;
      if (touched_before && may_recycle(a, b, contacts[read], settings.contact_recycle_distance,
                                        settings.speculative_margin)) {
        // The walk's own updates of a kept contact, on the old one in place: no other pair
        // reads it, and the walk copies it to its place in the new list.
        Contact& contact = contacts[read];
        job.recycle = true;
        recycle_manifold(a, b, contact);
        job.ghost = is_ghost(a, b, contact, settings, dt);
        if (job.ghost) continue;
        contact.recycled = true;
        forget_bounced_impulses(contact);
        mix_materials(a, b, settings, contact);
        continue;
      }
      job.manifold = collide(a.shape, a.transform, b.shape, b.transform,
                             pair_margin(a, b, reach, settings, pair));
    }
  });
}

}  // namespace

int update_contacts(const std::vector<Body>& bodies, const std::vector<BodyPair>& pairs,
                    const std::vector<float>& reach, const WorldSettings& settings, float dt,
                    const ContactFilter& filter, std::vector<Contact>& contacts,
                    std::vector<Contact>& spill, ContactVisitor* visitor, WorkerPool* pool,
                    std::vector<NarrowPhaseJob>* jobs) {
  // The pairs' independent parts first, side by side (their answers are the walk's own).
  const NarrowPhaseJob* job = nullptr;  // the current pair's, during the walk
  if (pool != nullptr && jobs != nullptr) {
    run_pair_jobs(bodies, pairs, reach, settings, dt, contacts, pool, *jobs);
  }
  // This step's contacts are written over last step's in the same list: slots [0, write) hold
  // the new list, and the old contacts not read yet are those displaced into `spill` (a ring,
  // oldest first) followed by the array's [array_read, old_count). Writing into a slot that
  // still holds an unread old contact moves that contact to the ring's back first, so the ring
  // holds no more contacts than the step has new ones ahead of the old (no allocation once warm,
  // and no second copy of the list). A kept contact that lies where it is written is updated in
  // place (no copy).
  const std::size_t old_count = contacts.size();
  std::size_t write = 0;
  std::size_t array_read = 0;
  std::size_t ring_head = 0;
  std::size_t ring_count = 0;
  auto ring_push = [&](const Contact& displaced) {
    if (ring_count == spill.size()) {  // full: unroll it in order, then grow at its end
      std::rotate(spill.begin(), spill.begin() + static_cast<std::ptrdiff_t>(ring_head), spill.end());
      ring_head = 0;
      spill.push_back(displaced);
    } else {
      spill[(ring_head + ring_count) % spill.size()] = displaced;
    }
    ++ring_count;
  };
  auto has_old = [&] { return ring_count > 0 || array_read < old_count; };
  // The next unread old contact (valid while `has_old()`).
  auto old_front = [&]() -> Contact& { return ring_count > 0 ? spill[ring_head] : contacts[array_read]; };
  auto pop_old = [&] {
    if (ring_count > 0) {
      ring_head = (ring_head + 1) % spill.size();
      --ring_count;
    } else {
      ++array_read;
    }
  };
  // The slot of new contact `write`: an unread old contact there moves to the ring first.
  auto slot = [&]() -> Contact& {
    if (write >= contacts.size()) return contacts.emplace_back();
    if (write == array_read && array_read < old_count) {
      ring_push(contacts[array_read]);
      ++array_read;
    }
    return contacts[write];
  };

  int point_total = 0;
  // One pair of shapes: shape `child_a` of `a` against shape `child_b` of `b`.
  auto update_pair = [&](const Body& a, const Body& b, std::uint16_t child_a, std::uint16_t child_b,
                         float margin) {
    auto before = [&](const Contact& old) {
      if (old.body_a.index != a.id.index) return old.body_a.index < a.id.index;
      if (old.body_b.index != b.id.index) return old.body_b.index < b.id.index;
      if (old.child_a != child_a) return old.child_a < child_a;
      return old.child_b < child_b;
    };
    while (has_old() && before(old_front())) pop_old();  // pairs that no longer meet
    const bool touched_before = has_old() && old_front().body_a == a.id &&
                                old_front().body_b == b.id && old_front().child_a == child_a &&
                                old_front().child_b == child_b;
    const bool recycle = job != nullptr ? touched_before && job->recycle
                                        : touched_before &&
                                              may_recycle(a, b, old_front(),
                                                          settings.contact_recycle_distance,
                                                          settings.speculative_margin);
    if (recycle) {
      Contact* kept = nullptr;
      if (ring_count == 0 && array_read == write) {
        kept = &contacts[write];  // where it lies: updated in place
        ++array_read;
      } else {
        const Contact old = old_front();
        pop_old();
        kept = &slot();
        *kept = old;
      }
      Contact& contact = *kept;
      if (job == nullptr) recycle_manifold(a, b, contact);  // else done by the workers
      if (job != nullptr ? job->ghost : is_ghost(a, b, contact, settings, dt)) {
        // Its slot is left to the next contact placed (or dropped when the list ends).
        if (write + 1 == contacts.size() && write >= old_count) contacts.pop_back();
        return;
      }
      if (job == nullptr) {
        contact.recycled = true;
        forget_bounced_impulses(contact);
        mix_materials(a, b, settings, contact);
      }
      point_total += contact.point_count;
      if (visitor) visitor->visit(write, contact);
      ++write;
      return;
    }
    const Manifold manifold = job != nullptr ? job->manifold
                              : a.compound || b.compound
                                  ? collide(shape_of(a, child_a), shape_transform(a, child_a),
                                            shape_of(b, child_b), shape_transform(b, child_b), margin)
                                  : collide(a.shape, a.transform, b.shape, b.transform, margin);
    if (manifold.point_count == 0) return;

    Contact contact;
    contact.body_a = a.id;
    contact.body_b = b.id;
    contact.child_a = child_a;
    contact.child_b = child_b;
    contact.normal = manifold.normal;
    contact.point_count = manifold.point_count;
    for (int i = 0; i < manifold.point_count; ++i) {
      contact.points[i].point = manifold.points[i].point;
      contact.points[i].depth = manifold.points[i].depth;
      contact.points[i].feature_id = manifold.points[i].feature_id;
    }
    if (is_ghost(a, b, contact, settings, dt)) return;
    mix_materials(a, b, settings, contact);
    remember_manifold_pose(a, b, contact);
    if (touched_before) {
      const Contact& old_contact = old_front();
      contact.enabled = old_contact.enabled;
      // A disabled pair stays disabled while its shapes overlap (re-enabling then would pop a
      // body through a one-way platform); once they are apart again, with speculative contacts
      // still inside the margin, the decision is taken afresh.
      if (!contact.enabled && deepest_depth(manifold) < -separated_gap) {
        contact.enabled = filter ? filter(view_of(a), view_of(b), manifold) : true;
      }
      contact.sliding = old_contact.sliding;
      contact.steps_at_static_limit = old_contact.steps_at_static_limit;
      contact.limit_slip = old_contact.limit_slip;
      carry_over_impulses(old_contact, contact);
    } else {
      // A contact that begins with its surfaces already slipping past each other slides
      // (kinetic friction) until it comes to rest; one that begins at rest sticks.
      contact.sliding = std::fabs(tangential_speed(a, b, contact)) > sticking_speed;
      if (filter) contact.enabled = filter(view_of(a), view_of(b), manifold);
    }
    point_total += contact.point_count;
    if (touched_before) pop_old();  // replaced by the fresh manifold
    Contact& placed = slot();
    placed = contact;
    if (visitor) visitor->visit(write, placed);
    ++write;
  };

  const bool have_jobs = pool != nullptr && jobs != nullptr;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const BodyPair& pair = pairs[p];
    const Body& a = bodies[pair.first];
    const Body& b = bodies[pair.second];
    const float margin = pair_margin(a, b, reach, settings, pair);
    if (!a.compound && !b.compound) {
      job = have_jobs ? &(*jobs)[p] : nullptr;
      update_pair(a, b, 0, 0, margin);
      continue;
    }
    job = nullptr;
    // A compound body: every pair of solid shapes whose layers meet and whose bounds come
    // within the margin, in (A's shape, B's shape) order.
    const int count_a = shape_count_of(a);
    const int count_b = shape_count_of(b);
    for (int i = 0; i < count_a; ++i) {
      if (is_sensor_shape(a, i)) continue;  // a sensor shape makes no contacts
      const Aabb bounds_a = compute_aabb(shape_of(a, i), shape_transform(a, i));
      for (int k = 0; k < count_b; ++k) {
        if ((layers_of(a, i) & layers_of(b, k)) == 0 || is_sensor_shape(b, k)) continue;
        Aabb bounds_b = compute_aabb(shape_of(b, k), shape_transform(b, k));
        bounds_b.lower -= vec2(margin);
        bounds_b.upper += vec2(margin);
        if (!bounds_a.overlaps(bounds_b)) continue;
        update_pair(a, b, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(k), margin);
      }
    }
  }
  contacts.resize(write);  // old contacts left unread (ring and array) no longer meet
  return point_total;
}

}  // namespace impulse2d

#include "core/collide/narrow_phase.h"

#include "core/collide.h"
#include "core/solver/contact_friction_state.h"
#include "core/solver/contact_recycle.h"
#include "core/solver/prefetch.h"
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
// world's mixing rules. Mixed into locals first: a store into `contact` could otherwise be
// taken to change a material and make the compiler read it again. (`inline`: so that the
// walk's path for a kept contact, taken by nearly every contact every step, inlines it.)
inline void mix_materials(const Body& a, const Body& b, const WorldSettings& settings,
                          Contact& contact) {
  const Material& material_a = material_of(a, contact.child_a);
  const Material& material_b = material_of(b, contact.child_b);
  const float static_friction = mix_friction(material_a.static_friction,
                                             material_b.static_friction, settings.friction_mixing);
  float dynamic_friction = mix_friction(material_a.dynamic_friction,
                                        material_b.dynamic_friction, settings.friction_mixing);
  // Mixing can put dynamic above static (e.g. root-sum-squares never does, but a custom
  // rule might); Coulomb's model needs static >= dynamic.
  if (dynamic_friction > static_friction) dynamic_friction = static_friction;
  const float restitution =
      mix_restitution(material_a.restitution, material_b.restitution, settings.restitution_mixing);
  contact.static_friction = static_friction;
  contact.dynamic_friction = dynamic_friction;
  contact.restitution = restitution;
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


// Asks the cache for the bodies of `pair` (no effect on results). The walks ask for the pair
// `prefetch_items_ahead` ahead and its old contact (about one old contact per pair).
void prefetch_pair(const std::vector<Body>& bodies, const BodyPair& pair) {
  prefetch_bytes(bodies[pair.first], 0, body_contact_bytes);
  prefetch_bytes(bodies[pair.second], 0, body_contact_bytes);
}

// The speculative margin (metres) pair (a, b) is collided with (`reach` per slot).
float pair_margin(const Body& a, const Body& b, const std::vector<float>& reach,
                  const WorldSettings& settings) {
  return settings.speculative_margin > 0.0f && a.speculative && b.speculative
             ? settings.speculative_margin + reach[a.id.index] + reach[b.id.index]
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
      if (i + prefetch_items_ahead < end) {
        prefetch_pair(bodies, pairs[i + prefetch_items_ahead]);
        const std::size_t old_ahead = read + prefetch_items_ahead;
        if (old_ahead < contacts.size()) prefetch_bytes(contacts[old_ahead]);
      }
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
                             pair_margin(a, b, reach, settings));
    }
  });
}

// This step's contacts written over last step's in the same list, in pair order: slots
// [0, write) hold the new list, and the old contacts not read yet are those displaced into
// `spill` (a ring, oldest first) followed by the array's [array_read, old_count). Writing into a
// slot that still holds an unread old contact moves that contact to the ring's back first, so
// the ring holds no more contacts than the step has new ones ahead of the old (no allocation
// once warm, and no second copy of the list). A kept contact that lies where it is written is
// updated in place (no copy).
class ContactListRewrite {
 public:
  ContactListRewrite(std::vector<Contact>& contacts, std::vector<Contact>& spill)
      : contacts_(contacts), spill_(spill), old_count_(contacts.size()) {}

  // Asks the cache for the old contact `ahead` contacts after the next (no effect on results).
  void prefetch_old(std::size_t ahead) const {
    if (ring_count_ == 0 && array_read_ + ahead < old_count_) {
      prefetch_bytes(contacts_[array_read_ + ahead]);
    }
  }

  // True while an old contact is left to read.
  bool has_old() const { return ring_count_ > 0 || array_read_ < old_count_; }

  // The next unread old contact (valid while `has_old()`).
  Contact& old_front() { return ring_count_ > 0 ? spill_[ring_head_] : contacts_[array_read_]; }

  // Reads past the next old contact.
  void pop_old() {
    if (ring_count_ > 0) {
      if (++ring_head_ == spill_.size()) ring_head_ = 0;  // (no division: this runs per contact)
      --ring_count_;
    } else {
      ++array_read_;
    }
  }

  // Reads the next old contact (valid while `has_old()`) into the slot of the next new contact
  // and returns it there, to be updated, then placed (`place`) or given up (`give_up_slot`).
  Contact& keep_old() {
    if (ring_count_ > 0) return keep_ring_front();
    Contact& kept = contacts_[write_];
    // Where it lies, it stays (no copy); else it lies further on and moves down.
    if (array_read_ != write_) kept = contacts_[array_read_];
    ++array_read_;
    return kept;
  }

  // The slot of the next new contact: an unread old contact there moves to the ring first.
  Contact& slot() {
    if (write_ >= contacts_.size()) return contacts_.emplace_back();
    if (write_ == array_read_ && array_read_ < old_count_) {
      ring_push(contacts_[array_read_]);
      ++array_read_;
    }
    return contacts_[write_];
  }

  // The contact in the slot joins the new list (as contact `placed()`); the next goes after it.
  void place() { ++write_; }

  // The slot's contact stays out of the new list: the slot is left to the next contact placed
  // (or dropped when the list ends).
  void give_up_slot() {
    if (write_ + 1 == contacts_.size() && write_ >= old_count_) contacts_.pop_back();
  }

  // Index in the new list of the contact in the slot.
  std::size_t placed() const { return write_; }

  // Ends the new list: old contacts left unread (ring and array) no longer meet.
  void finish() { contacts_.resize(write_); }

 private:
  // `keep_old` when the next old contact is the ring's front. Not inlined: only a step that
  // places more new contacts than it drops takes this way, and `keep_old` stays small.
  __attribute__((noinline)) Contact& keep_ring_front() {
    // A copy: an old contact displaced from the slot may take the front's place in the ring.
    const Contact old = spill_[ring_head_];
    pop_old();
    Contact& kept = slot();
    kept = old;
    return kept;
  }

  void ring_push(const Contact& displaced) {
    if (ring_count_ == spill_.size()) {  // full: unroll it in order, then grow at its end
      std::rotate(spill_.begin(), spill_.begin() + static_cast<std::ptrdiff_t>(ring_head_), spill_.end());
      ring_head_ = 0;
      spill_.push_back(displaced);
    } else {
      const std::size_t back = ring_head_ + ring_count_;  // < 2 * size: wraps once at most
      spill_[back < spill_.size() ? back : back - spill_.size()] = displaced;
    }
    ++ring_count_;
  }

  std::vector<Contact>& contacts_;
  std::vector<Contact>& spill_;
  const std::size_t old_count_;
  std::size_t write_ = 0;
  std::size_t array_read_ = 0;
  std::size_t ring_head_ = 0;
  std::size_t ring_count_ = 0;
};

// The walk over the step's pairs, in order, that builds this step's contact list over last
// step's (`ContactListRewrite`).
class NarrowPhaseWalk {
 public:
  NarrowPhaseWalk(const std::vector<float>& reach, const WorldSettings& settings, float dt,
                  const ContactFilter& filter, ContactVisitor* visitor,
                  std::vector<Contact>& contacts, std::vector<Contact>& spill)
      : reach_(reach), settings_(settings), dt_(dt), filter_(filter), visitor_(visitor),
        list_(contacts, spill) {}

  // Shape `child_a` of `a` against shape `child_b` of `b` (0 and 0 for a pair of single-shape
  // bodies): last step's contact kept if it may be, else collided afresh.
  void update_shapes(const Body& a, const Body& b, std::uint16_t child_a, std::uint16_t child_b) {
    const Contact* old = old_contact_of(a, b, child_a, child_b);
    if (old == nullptr || !may_recycle(a, b, *old, settings_.contact_recycle_distance,
                                       settings_.speculative_margin)) {
      collide_afresh(a, b, child_a, child_b, nullptr, old);
      return;
    }
    Contact& contact = list_.keep_old();
    recycle_manifold(a, b, contact);
    if (is_ghost(a, b, contact, settings_, dt_)) {
      list_.give_up_slot();
      return;
    }
    contact.recycled = true;
    forget_bounced_impulses(contact);
    mix_materials(a, b, settings_, contact);
    place(contact);
  }

  // As `update_shapes` for a pair of single-shape bodies, with the workers' answers `job`
  // (`run_pair_jobs`) in place of its own.
  void update_shapes(const Body& a, const Body& b, const NarrowPhaseJob& job) {
    const Contact* old = old_contact_of(a, b, 0, 0);
    if (old == nullptr || !job.recycle) {
      collide_afresh(a, b, 0, 0, &job, old);
      return;
    }
    Contact& contact = list_.keep_old();  // already updated by the worker
    if (job.ghost) {
      list_.give_up_slot();
      return;
    }
    place(contact);
  }

  // Pair (a, b) with a compound body: every pair of solid shapes whose layers meet and whose
  // bounds come within the margin, in (A's shape, B's shape) order.
  void update_compound_pair(const Body& a, const Body& b) {
    const float margin = pair_margin(a, b, reach_, settings_);
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
        update_shapes(a, b, static_cast<std::uint16_t>(i), static_cast<std::uint16_t>(k));
      }
    }
  }

  // Asks the cache for the old contact `ahead` contacts after the next (no effect on results).
  void prefetch_old(std::size_t ahead) const { list_.prefetch_old(ahead); }

  // Ends the list; returns the number of manifold points made.
  int finish() {
    list_.finish();
    return point_total_;
  }

 private:
  // Last step's contact of shape `child_a` of `a` against shape `child_b` of `b`, the next old
  // contact once those of pairs before this one are read past (those pairs no longer meet);
  // null if the pair had none.
  const Contact* old_contact_of(const Body& a, const Body& b, std::uint16_t child_a,
                                std::uint16_t child_b) {
    while (list_.has_old()) {
      const Contact& old = list_.old_front();
      // Most often it is this pair's: asked first.
      if (old.body_a == a.id && old.body_b == b.id && old.child_a == child_a &&
          old.child_b == child_b) {
        return &old;
      }
      // Else it is a pair that came before, or one that comes later (or a body of the pair
      // since destroyed whose slot is now reused).
      const bool before = old.body_a.index != a.id.index   ? old.body_a.index < a.id.index
                          : old.body_b.index != b.id.index ? old.body_b.index < b.id.index
                          : old.child_a != child_a         ? old.child_a < child_a
                                                           : old.child_b < child_b;
      if (!before) return nullptr;
      list_.pop_old();
    }
    return nullptr;
  }

  // For `update_shapes` when last step's contact `old` (null if none; else the next old
  // contact) is not kept: a contact from a fresh manifold (the job's, if not null), unless the
  // shapes are apart. Not inlined, so that the common case, a kept contact, does not pay for
  // its stack frame.
  __attribute__((noinline)) void collide_afresh(const Body& a, const Body& b, std::uint16_t child_a,
                                                std::uint16_t child_b, const NarrowPhaseJob* job,
                                                const Contact* old) {
    const Manifold manifold =
        job != nullptr ? job->manifold
        : a.compound || b.compound
            ? collide(shape_of(a, child_a), shape_transform(a, child_a), shape_of(b, child_b),
                      shape_transform(b, child_b), pair_margin(a, b, reach_, settings_))
            : collide(a.shape, a.transform, b.shape, b.transform,
                      pair_margin(a, b, reach_, settings_));
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
    if (is_ghost(a, b, contact, settings_, dt_)) return;
    mix_materials(a, b, settings_, contact);
    remember_manifold_pose(a, b, contact);
    if (old != nullptr) {
      const Contact& old_contact = *old;
      contact.enabled = old_contact.enabled;
      // A disabled pair stays disabled while its shapes overlap (re-enabling then would pop a
      // body through a one-way platform); once they are apart again, with speculative contacts
      // still inside the margin, the decision is taken afresh.
      if (!contact.enabled && deepest_depth(manifold) < -separated_gap) {
        contact.enabled = filter_ ? filter_(view_of(a), view_of(b), manifold) : true;
      }
      contact.sliding = old_contact.sliding;
      // What the pair's touch was (`enabled && touching`, as the events after the last step
      // saw it): the step's touch tally then sees a change only where the touch changes.
      contact.touching = old_contact.enabled && old_contact.touching;
      contact.steps_at_static_limit = old_contact.steps_at_static_limit;
      contact.limit_slip = old_contact.limit_slip;
      carry_over_impulses(old_contact, contact);
      list_.pop_old();  // replaced by the fresh manifold
    } else {
      // A contact that begins with its surfaces already slipping past each other slides
      // (kinetic friction) until it comes to rest; one that begins at rest sticks.
      contact.sliding = std::fabs(tangential_speed(a, b, contact)) > sticking_speed;
      if (filter_) contact.enabled = filter_(view_of(a), view_of(b), manifold);
    }
    Contact& placed = list_.slot();
    placed = contact;
    place(placed);
  }

  // The contact in the list's slot joins the new list.
  void place(Contact& contact) {
    point_total_ += contact.point_count;
    if (visitor_) visitor_->visit(list_.placed(), contact);
    list_.place();
  }

  const std::vector<float>& reach_;
  const WorldSettings& settings_;
  const float dt_;
  const ContactFilter& filter_;
  ContactVisitor* const visitor_;
  ContactListRewrite list_;
  int point_total_ = 0;  // manifold points made
};

}  // namespace

int update_contacts(const std::vector<Body>& bodies, const std::vector<BodyPair>& pairs,
                    const std::vector<float>& reach, const WorldSettings& settings, float dt,
                    const ContactFilter& filter, std::vector<Contact>& contacts,
                    std::vector<Contact>& spill, ContactVisitor* visitor, WorkerPool* pool,
                    std::vector<NarrowPhaseJob>* jobs) {
  // The pairs' independent parts first, side by side (their answers are the walk's own).
  const bool have_jobs = pool != nullptr && jobs != nullptr;
  if (have_jobs) run_pair_jobs(bodies, pairs, reach, settings, dt, contacts, pool, *jobs);
  NarrowPhaseWalk walk(reach, settings, dt, filter, visitor, contacts, spill);
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    if (p + prefetch_items_ahead < pairs.size()) {
      prefetch_pair(bodies, pairs[p + prefetch_items_ahead]);
      walk.prefetch_old(prefetch_items_ahead);
    }
    const Body& a = bodies[pairs[p].first];
    const Body& b = bodies[pairs[p].second];
    if (a.compound || b.compound) {
      walk.update_compound_pair(a, b);
    } else if (have_jobs) {
      walk.update_shapes(a, b, (*jobs)[p]);
    } else {
      walk.update_shapes(a, b, 0, 0);
    }
  }
  return walk.finish();
}

}  // namespace impulse2d

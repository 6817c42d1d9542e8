#pragma once
/// @file narrow_phase.h
/// Turns candidate pairs into persistent contacts: collide through the jump table, mix the
/// materials, carry impulses over from last step's points with the same feature ids, and keep
/// a contact filter's decision for as long as the pair keeps touching.

#include "core/collide/broad_phase.h"
#include "core/contact.h"
#include "core/manifold.h"
#include "core/solver/worker_pool.h"
#include "core/solver/contact_visitor.h"
#include "core/world.h"

#include <vector>

namespace impulse2d {

/// What the workers find for one broad-phase pair before the narrow phase's walk
/// (`update_contacts` with a pool).
struct NarrowPhaseJob {
  /// The pair's fresh manifold (when neither `recycle` nor `compound`).
  Manifold manifold;
  /// Last step's contact of the pair may be kept (`may_recycle`): no collision was made, and
  /// that contact, still in the old list, was already updated as the walk would update it
  /// (its manifold recycled and, unless `ghost`, its materials mixed).
  bool recycle = false;
  /// With `recycle`: the updated contact would only stop bodies passing each other (it is left
  /// out).
  bool ghost = false;
  /// A body of the pair is compound: the walk collides its pairs of shapes itself.
  bool compound = false;
};

/// Turns `contacts`, last step's contacts sorted by pair, into this step's (sorted by pair)
/// from `pairs`, each pair collided with the speculative margin `settings.speculative_margin +
/// reach[a] + reach[b]` (metres; `reach` per slot, see `speculative_reach.h`); kept contacts
/// are updated in place. A contact whose points are all apart and that would only stop bodies
/// passing each other within the coming `dt` seconds is left out (`is_ghost_contact`). `spill` is scratch space: a ring for the old contacts that new ones displace before they are read, never more than the step's new contacts ahead of old ones (reused: no allocation once warm). `filter`
/// may be empty. `visitor` (may be null) sees each contact of the new list as soon as it is
/// written. Returns the number of manifold points made.
///
/// With a `pool`, each pair's costly and independent part (the recycling test against last
/// step's contact of the pair, or else the collision) is first done for every pair of two
/// single-shape bodies side by side on its workers, into `jobs` (scratch, reused); the walk
/// that builds the list then takes those answers instead of computing them, in the same order,
/// so the list is the same bits. Pairs with a compound body are collided in the walk.
int update_contacts(const std::vector<Body>& bodies, const std::vector<BodyPair>& pairs,
                    const std::vector<float>& reach, const WorldSettings& settings, float dt,
                    const ContactFilter& filter, std::vector<Contact>& contacts,
                    std::vector<Contact>& spill, ContactVisitor* visitor,
                    WorkerPool* pool = nullptr, std::vector<NarrowPhaseJob>* jobs = nullptr);

}  // namespace impulse2d

#pragma once
/// @file narrow_phase.h
/// Turns candidate pairs into persistent contacts: collide through the jump table, mix the
/// materials, carry impulses over from last step's points with the same feature ids, and keep
/// a contact filter's decision for as long as the pair keeps touching.

#include "core/collide/broad_phase.h"
#include "core/contact.h"
#include "core/solver/contact_visitor.h"
#include "core/world.h"

#include <vector>

namespace impulse2d {

/// Turns `contacts`, last step's contacts sorted by pair, into this step's (sorted by pair)
/// from `pairs`, each pair collided with the speculative margin `settings.speculative_margin +
/// reach[a] + reach[b]` (metres; `reach` per slot, see `speculative_reach.h`); kept contacts
/// are updated in place. A contact whose points are all apart and that would only stop bodies
/// passing each other within the coming `dt` seconds is left out (`is_ghost_contact`). `spill` is scratch space (reused: no allocation once warm). `filter`
/// may be empty. `visitor` (may be null) sees each contact of the new list as soon as it is
/// written. Returns the number of manifold points made.
int update_contacts(const std::vector<Body>& bodies, const std::vector<BodyPair>& pairs,
                    const std::vector<float>& reach, const WorldSettings& settings, float dt,
                    const ContactFilter& filter, std::vector<Contact>& contacts,
                    std::vector<Contact>& spill, ContactVisitor* visitor);

}  // namespace impulse2d

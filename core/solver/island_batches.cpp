#include "core/solver/island_batches.h"

#include <numeric>

namespace impulse2d {

void IslandBatches::begin(std::size_t slot_count) {
  parent_.resize(slot_count);
  std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  contact_slot_.clear();
  batch_count_ = 0;
}

std::uint32_t IslandBatches::root_of(std::uint32_t slot) {
  // Path halving: each slot on the way is pointed at its grandparent (one walk).
  while (parent_[slot] != slot) {
    const std::uint32_t grandparent = parent_[parent_[slot]];
    parent_[slot] = grandparent;
    slot = grandparent;
  }
  return slot;
}

void IslandBatches::add_contact(std::uint32_t a, bool a_joins, std::uint32_t b, bool b_joins) {
  if (a_joins && b_joins) {
    const std::uint32_t root_a = root_of(a);
    const std::uint32_t root_b = root_of(b);
    // The smaller slot becomes the root: the forest depends only on the contacts' order.
    if (root_a < root_b) {
      parent_[root_b] = root_a;
    } else if (root_b < root_a) {
      parent_[root_a] = root_b;
    }
  }
  contact_slot_.push_back(a_joins ? a : b);
}

void IslandBatches::make_batches() {
  const std::size_t slots = parent_.size();
  root_contacts_.assign(slots, 0);
  root_batch_.assign(slots, no_batch);
  for (std::uint32_t& slot : contact_slot_) {
    slot = root_of(slot);  // from here on: the contact's island's root
    ++root_contacts_[slot];
  }
  contact_batch_.resize(contact_slot_.size());
  std::size_t batch = 0;
  std::size_t in_batch = 0;  // contacts of the open batch
  for (std::size_t k = 0; k < contact_slot_.size(); ++k) {
    const std::uint32_t root = contact_slot_[k];
    if (root_batch_[root] == no_batch) {
      if (in_batch >= target_contacts) {
        ++batch;
        in_batch = 0;
      }
      root_batch_[root] = static_cast<std::uint32_t>(batch);
      in_batch += root_contacts_[root];
    }
    contact_batch_[k] = root_batch_[root];
  }
  batch_count_ = contact_slot_.empty() ? 0 : batch + 1;
}

void IslandBatches::sort_bodies_by_batch() {
  // A counting sort of the slots by batch, the rest batch last, each batch's slots ascending.
  body_begin_.assign(batch_count_ + 2, 0);
  for (const std::uint32_t batch : slot_batch_) {
    if (batch != no_batch) ++body_begin_[batch + 1];
  }
  std::partial_sum(body_begin_.begin(), body_begin_.end(), body_begin_.begin());
  body_slots_.resize(body_begin_.back());
  next_slot_.assign(body_begin_.begin(), body_begin_.end() - 1);
  for (std::size_t slot = 0; slot < slot_batch_.size(); ++slot) {
    const std::uint32_t batch = slot_batch_[slot];
    if (batch != no_batch) body_slots_[next_slot_[batch]++] = static_cast<std::uint32_t>(slot);
  }
}

}  // namespace impulse2d
